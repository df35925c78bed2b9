// `compax bed` through the real executable: a small two-material bed in
// the square die with both formulations; at every jammed step the wall
// forces balance (Newton's third law, no gravity: lower = upper punch,
// x_lower = x_upper, y_lower = y_upper), the discrepancy table is the
// relative difference of the two load columns, and bad input is rejected.

#include "app_test_support.h"

#include <cmath>

using compax::testing::AppTest;
using compax::testing::Csv;

class BedCommand : public AppTest
{
};

TEST_F(BedCommand, SmallBedBalancesWallForces)
{
  write("small.prm",
        "set Die width = 0.6e-3\n"
        "set Number of particles = 40\n"
        "set Final relative density = 0.60\n"
        "set Density step = 0.01\n"
        "set Jamming pressure = 2e5\n");
  const auto r = compax("bed small.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv   bed(folder / "out" / "bed.csv");
  const auto &f = bed.text.at("formulation");
  ASSERT_FALSE(f.empty());
  int jammed[2] = {0, 0};
  for (std::size_t i = 0; i < f.size(); ++i)
    {
      if (bed.column.at("jammed")[i] != 1.0)
        continue;
      ++jammed[f[i] == "nonlocal"];
      const double up  = bed.column.at("upper_punch")[i];
      const double tol = 1e-4 * up;
      EXPECT_NEAR(bed.column.at("lower_punch")[i], up, tol) << i;
      EXPECT_NEAR(bed.column.at("x_lower")[i],
                  bed.column.at("x_upper")[i],
                  tol);
      EXPECT_NEAR(bed.column.at("y_lower")[i],
                  bed.column.at("y_upper")[i],
                  tol);
      const double mean
        = 0.25
          * (bed.column.at("x_lower")[i] + bed.column.at("x_upper")[i]
             + bed.column.at("y_lower")[i] + bed.column.at("y_upper")[i]);
      EXPECT_NEAR(bed.column.at("lateral")[i], mean, 1e-9 * (mean + 1e-30));
      EXPECT_LE(bed.column.at("relative_residual")[i], 1e-6);
    }
  EXPECT_GT(jammed[0], 0);
  EXPECT_GT(jammed[1], 0);

  const Csv   d(folder / "out" / "discrepancy.csv");
  const auto &rho = d.column.at("relative_density");
  ASSERT_FALSE(rho.empty());
  for (std::size_t i = 0; i < rho.size(); ++i)
    if (!d.text.at("load_discrepancy")[i].empty())
      {
        const double h = d.column.at("hertz_load")[i];
        EXPECT_NEAR(d.column.at("load_discrepancy")[i],
                    (d.column.at("nonlocal_load")[i] - h) / h,
                    1e-9);
      }
}

TEST_F(BedCommand, RejectsUnknownFormulation)
{
  expect_prm_rejected("bed",
                      "set Formulations = hertz, mindlin\n",
                      "Formulations");
}

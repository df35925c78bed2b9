// `compax database` through the real executable on a small cell: the
// fitted cap passes through the compaction state it was fitted to (the
// yield function of the Drucker-Prager Cap, written out here, vanishes
// there), the shear line through the two shear failures, unloading ends
// at a vanishing axial stress, the table is one `compax tablet` accepts,
// and bad input is rejected.
#include "app_test_support.h"

#include <cmath>

using compax::testing::AppTest;
using compax::testing::Csv;

namespace
{
  const std::string small_database = "subsection Packing\n"
                                     " set Number of particles = 80\n"
                                     " set Seed = 5\n"
                                     "end\n"
                                     "subsection Paths\n"
                                     " set Final relative density = 0.76\n"
                                     " set Branch densities = 0.70, 0.76\n"
                                     " set Shear steps = 6\n"
                                     "end\n";
} // namespace

using DatabaseCommand = AppTest;

TEST_F(DatabaseCommand, FittedCapPassesThroughTheCompactionStates)
{
  write("db.prm", small_database);
  const auto r = compax("database db.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv rows(folder / "out" / "database.csv");
  const Csv fit(folder / "out" / "dpc_table.csv");
  const Csv branches(folder / "out" / "branches.csv");
  ASSERT_EQ(fit.column.at("relative_density").size(), 2u);

  for (std::size_t b = 0; b < 2; ++b)
    {
      const double rho = fit.column.at("relative_density")[b];
      // The compaction row at the branch density.
      double p = 0.0, q = 0.0;
      bool   found = false;
      for (std::size_t k = 0; k < rows.column.at("branch").size(); ++k)
        if (rows.text.at("path")[k] == "compaction"
            && std::abs(rows.column.at("relative_density")[k] - rho) < 1e-9)
          {
            p     = rows.column.at("p")[k];
            q     = rows.column.at("q")[k];
            found = true;
          }
      ASSERT_TRUE(found) << "no compaction row at " << rho;
      const double d = fit.column.at("cohesion")[b];
      const double tb
        = std::tan(fit.column.at("friction_angle_deg")[b] * M_PI / 180.0);
      const double R  = fit.column.at("cap_eccentricity")[b];
      const double pb = fit.column.at("cap_pressure")[b];
      const double pa = (pb - R * d) / (1.0 + R * tb);
      // On the cap (F_c = 0) ...
      const double Fc = std::hypot(p - pa, R * q) - R * (d + pa * tb);
      EXPECT_NEAR(Fc, 0.0, 1e-8 * pb);
      // ... where the flow normal has the uniaxial-strain ratio 2/3.
      EXPECT_NEAR(R * R * q / (p - pa), 2.0 / 3.0, 1e-8);
      EXPECT_GT(fit.column.at("youngs_modulus")[b], 0.0);
      const double nu = fit.column.at("poisson_ratio")[b];
      EXPECT_TRUE(nu > -1.0 && nu < 0.5) << nu;

      // Unloading stops at the first state without axial compression.
      std::vector<double> sigma_zz;
      for (std::size_t k = 0; k < rows.column.at("branch").size(); ++k)
        if (rows.column.at("branch")[k] == double(b)
            && rows.text.at("path")[k] == "unloading")
          sigma_zz.push_back(rows.column.at("sigma_zz")[k]);
      ASSERT_FALSE(sigma_zz.empty());
      EXPECT_GE(sigma_zz.back(), 0.0);
      for (std::size_t k = 0; k + 1 < sigma_zz.size(); ++k)
        EXPECT_LT(sigma_zz[k], 0.0);
    }
  // The cap pressure grows with density.
  EXPECT_GT(fit.column.at("cap_pressure")[1], fit.column.at("cap_pressure")[0]);

  // The table drives the continuum tablet model.
  write("tablet.prm",
        "subsection Material\n set DPC table = out/dpc_table.csv\nend\n");
  const auto t = compax("tablet tablet.prm --check");
  EXPECT_EQ(t.exit_code, 0) << t.err;
}

TEST_F(DatabaseCommand, RejectsBranchDensitiesOutOfOrder)
{
  write("bad.prm",
        "subsection Paths\n set Branch densities = 0.80, 0.75\nend\n");
  expect_rejected(compax("database bad.prm -o out"), "Branch densities");
}

TEST_F(DatabaseCommand, RejectsBranchBeyondFinalDensity)
{
  write("bad.prm",
        "subsection Paths\n set Final relative density = 0.8\n"
        " set Branch densities = 0.70, 0.85\nend\n");
  expect_rejected(compax("database bad.prm -o out"), "Branch densities");
}

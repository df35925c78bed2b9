// `compax tablet` on particle-derived behaviour: Material/Model =
// multiscale-database builds the RVE database, fits the Drucker-Prager Cap
// and runs the cycle on it; checked against mass conservation, global
// equilibrium in a frictionless die and the table it wrote.
#include "app_test_support.h"

#include <cmath>

using compax::testing::AppTest;
using compax::testing::Csv;

using TabletMultiscale = AppTest;

TEST_F(TabletMultiscale, DatabaseMaterialRunsTheCycleOnTheFittedCap)
{
  write("ms.prm",
        "subsection Mesh\n  set Radial cells = 3\nend\n"
        "subsection Material\n  set Model = multiscale-database\nend\n"
        "subsection Die\n  set Wall friction coefficient = 0\nend\n"
        "subsection Process\n  set Compaction steps = 30\n"
        "  set Unloading steps = 8\n  set Ejection steps = 0\nend\n"
        "subsection Output\n  set Write fields = false\nend\n"
        "subsection Multiscale\n"
        "  subsection Packing\n    set Number of particles = 80\n  end\n"
        "  subsection Paths\n    set Final relative density = 0.80\n"
        "    set Branch densities = 0.70, 0.75, 0.80\n"
        "    set Shear steps = 6\n  end\n"
        "end\n");
  const auto r = compax("tablet ms.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv table(folder / "out" / "database" / "dpc_table.csv");
  ASSERT_EQ(table.rows(), 3u);
  const Csv csv(folder / "out" / "tablet.csv");
  ASSERT_EQ(csv.rows(), 1u + 30 + 8);
  // Mass: the compact fills the die, rho = rho_0 H_0 / (H_0 - stroke).
  EXPECT_NEAR(csv.column.at("mean_relative_density")[30]
                / (0.5 * 7e-3 / (7e-3 - 3.11e-3)),
              1.0,
              1e-3);
  // Frictionless die: the punches carry the same force at every step.
  const double peak = csv.column.at("upper_punch_pressure")[30];
  EXPECT_GT(peak, 1e6);
  for (std::size_t k = 1; k <= 30; ++k)
    EXPECT_NEAR(csv.column.at("lower_punch_pressure")[k],
                csv.column.at("upper_punch_pressure")[k],
                1e-6 * peak)
      << "row " << k;
}

TEST_F(TabletMultiscale, Fe2MaterialIsAcceptedAtCheck)
{
  write("fe2.prm",
        "subsection Material\n  set Model = multiscale-fe2\nend\n"
        "subsection Multiscale\n  set Pool size = 2\nend\n");
  const auto r = compax("tablet fe2.prm --check");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(TabletMultiscale, BadDatabasePathsAreBadInput)
{
  write("bad.prm",
        "subsection Material\n  set Model = multiscale-database\nend\n"
        "subsection Multiscale\n  subsection Paths\n"
        "    set Branch densities = 0.8, 0.7\n  end\nend\n");
  expect_rejected(compax("tablet bad.prm -o out"),
                  "Multiscale/Paths/Branch densities");
}

TEST_F(TabletMultiscale, Fe2RunCannotResumeWithoutItsRveStates)
{
  write("bad.prm",
        "subsection Material\n  set Model = multiscale-fe2\nend\n"
        "subsection Output\n  set Resume from = earlier\nend\n");
  expect_rejected(compax("tablet bad.prm -o out"), "Resume from");
}

// `compax tablet` on particle-derived behaviour: Material/Model =
// multiscale-database builds the RVE database, fits the Drucker-Prager Cap
// and runs the cycle on it; checked against mass conservation, global
// equilibrium in a frictionless die and the table it wrote. A
// multiscale-fe2 run resumed from its checkpoint (RVEs included) repeats
// the uninterrupted run.
#include "app_test_support.h"

#include <cmath>
#include <filesystem>

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
  expect_prm_rejected(
    "tablet",
    "subsection Material\n  set Model = multiscale-database\nend\n"
    "subsection Multiscale\n  subsection Paths\n"
    "    set Branch densities = 0.8, 0.7\n  end\nend\n",
    "Multiscale/Paths/Branch densities");
}

TEST_F(TabletMultiscale, Fe2RunResumedFromItsCheckpointIsTheUninterruptedRun)
{
  // A tiny FE2 cycle (one cell, two 20-particle packings): compaction
  // through the jamming of the points, then unloading; checkpoint after
  // step 8, when every point is a jammed RVE.
  const std::string base
    = "subsection Mesh\n  set Radial cells = 1\nend\n"
      "subsection Material\n  set Model = multiscale-fe2\nend\n"
      "subsection Die\n  set Wall friction coefficient = 0\nend\n"
      "subsection Process\n  set Compaction steps = 10\n"
      "  set Unloading steps = 3\n  set Ejection steps = 0\nend\n"
      "subsection Output\n  set Write fields = false\n"
      "  set Checkpoint interval = 8\nend\n"
      "subsection Multiscale\n  set Pool size = 2\n"
      "  subsection Packing\n    set Number of particles = 20\n  end\n"
      "end\n";
  write("full.prm", base);
  write("resume.prm",
        base + "subsection Output\n  set Resume from = full\nend\n");
  const auto full = compax("tablet full.prm -o full");
  ASSERT_EQ(full.exit_code, 0) << full.err;
  // The run's last checkpoint (step 8) holds the RVEs of its points.
  ASSERT_TRUE(std::filesystem::is_regular_file(folder / "full" / "checkpoint"
                                               / "rve.0.h5"));
  const auto resumed = compax("tablet resume.prm -o resumed");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("Resuming after step 8"), std::string::npos)
    << resumed.out;

  // Same binary, same RVEs (the running material refreshes its contact
  // lists at the checkpoint as loading does), same Newton path: the
  // resumed cycle repeats the uninterrupted one.
  const Csv a(folder / "full" / "tablet.csv");
  const Csv b(folder / "resumed" / "tablet.csv");
  ASSERT_EQ(a.rows(), 1u + 10 + 3);
  expect_equal_rows(a,
                    b,
                    {"upper_punch_pressure",
                     "lower_punch_pressure",
                     "die_wall_pressure",
                     "mean_relative_density",
                     "mean_stress"},
                    9);
  // The points were jammed RVEs at the checkpoint (the elastic floor alone
  // carries ~0.5 MPa at this density) and were compacted further after it:
  // the resumed steps ran on the loaded cells.
  const auto &upper = a.column.at("upper_punch_pressure");
  EXPECT_GT(upper[8], 5e6);
  EXPECT_GT(upper[10], upper[8]);

  // A checkpoint of other RVEs (another packing) is refused as bad input,
  // naming the entry that differs.
  write("other.prm",
        base
          + "subsection Output\n  set Resume from = full\nend\n"
            "subsection Multiscale\n  subsection Packing\n"
            "    set Number of particles = 21\n  end\nend\n");
  const auto other = compax("tablet other.prm -o other");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("Multiscale/Packing/Number of particles = 20 in "
                           "the archive, 21 here"),
            std::string::npos)
    << other.err;
}

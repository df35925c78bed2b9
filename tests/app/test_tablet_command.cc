// `compax tablet` end to end: the shipped parameter files against closed
// forms, a short DPC cycle against mass conservation and Coulomb's law,
// and bad input. Skipped until the command is registered in the CLI.
#include "app_test_support.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

using compax::testing::AppTest;
using compax::testing::Csv;
using compax::testing::expect_columns;

namespace
{
  class TabletApp : public AppTest
  {
  protected:
    static std::string
    shipped(const std::string &name)
    {
      return std::string(COMPAX_SOURCE_DIR) + "/apps/parameters/" + name;
    }
  };
} // namespace

TEST_F(TabletApp, FrictionlessElasticDieGivesUniaxialStrain)
{
  const auto r = compax("tablet '" + shipped("tablet_elastic_frictionless.prm")
                        + "' -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv csv(folder / "out" / "tablet.csv");
  ASSERT_EQ(csv.rows(), 2u);
  // E = 2 GPa, nu = 0.3, eps = 0.5 um / 5 mm.
  const double E = 2e9, nu = 0.3, eps = 0.5e-6 / 5e-3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu     = E / (2 * (1 + nu));
  EXPECT_NEAR(csv.column.at("upper_punch_pressure")[1]
                / ((lambda + 2 * mu) * eps),
              1.0,
              1e-5);
  EXPECT_NEAR(csv.column.at("lower_punch_pressure")[1]
                / ((lambda + 2 * mu) * eps),
              1.0,
              1e-5);
  EXPECT_NEAR(csv.column.at("die_wall_pressure")[1] / (lambda * eps),
              1.0,
              1e-5);
  // Mean stress, tension positive: -(lambda + 2 mu + 2 lambda) eps / 3.
  EXPECT_NEAR(csv.column.at("mean_stress")[1]
                / (-(3 * lambda + 2 * mu) * eps / 3),
              1.0,
              1e-5);
}

TEST_F(TabletApp, WallFrictionFollowsJanssen)
{
  const auto r
    = compax("tablet '" + shipped("tablet_elastic_janssen.prm") + "' -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv    csv(folder / "out" / "tablet.csv");
  const auto   n     = csv.rows() - 1;
  const double ratio = csv.column.at("lower_punch_force")[n]
                       / csv.column.at("upper_punch_force")[n];
  const double K = 0.3 / 0.7, mu = 0.2, H_over_D = 1.0;
  EXPECT_NEAR(ratio / std::exp(-4 * mu * K * H_over_D), 1.0, 0.01);
}

TEST_F(TabletApp, DpcCycleConservesMassAndEjectsByCoulombFriction)
{
  write("short.prm",
        "subsection Mesh\n  set Radial cells = 4\nend\n"
        "subsection Process\n  set Compaction steps = 30\n"
        "  set Unloading steps = 8\n  set Ejection steps = 20\nend\n"
        "subsection Output\n  set Field interval = 20\nend\n");
  const auto r = compax("tablet short.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Tablet cycle completed"), std::string::npos);
  const Csv csv(folder / "out" / "tablet.csv");
  expect_columns(csv,
                 {"time",
                  "stage",
                  "upper_punch_displacement",
                  "upper_punch_pressure",
                  "lower_punch_pressure",
                  "die_wall_pressure",
                  "ejection_force",
                  "mean_relative_density"});
  ASSERT_EQ(csv.rows(), 1u + 30 + 8 + 20);
  // End of compaction: the compact fills the die between the punches, so
  // rho = rho_0 H_0 / (H_0 - stroke) (defaults: 0.5, 7 mm, 3.11 mm).
  EXPECT_NEAR(csv.column.at("mean_relative_density")[30]
                / (0.5 * 7e-3 / (7e-3 - 3.11e-3)),
              1.0,
              1e-3);
  EXPECT_GT(csv.column.at("upper_punch_pressure")[30], 50e6);
  // Ejection rows where the whole wall slides: F = mu N (mu = 0.25).
  unsigned int checked = 0;
  for (std::size_t k = 39; k < csv.rows(); ++k)
    if (csv.column.at("sliding_fraction")[k] == 1.0
        && csv.column.at("die_wall_normal_force")[k] > 1.0)
      {
        ++checked;
        EXPECT_NEAR(csv.column.at("ejection_force")[k]
                      / (0.25 * csv.column.at("die_wall_normal_force")[k]),
                    1.0,
                    1e-5)
          << "row " << k;
      }
  EXPECT_GT(checked, 5u);
  // Out of the die at the end, and free: its mean stress, the virial of
  // the tractions on it over its volume, vanishes by equilibrium (to the
  // Newton tolerance; the compacted one's is tens of MPa), however much
  // residual stress it holds.
  EXPECT_EQ(csv.column.at("die_wall_normal_force").back(), 0.0);
  EXPECT_LT(std::abs(csv.column.at("mean_stress").back()),
            1e-4 * csv.column.at("upper_punch_pressure")[30]);
  EXPECT_LT(csv.column.at("mean_stress")[30],
            -0.25 * csv.column.at("upper_punch_pressure")[30]);
  EXPECT_TRUE(std::filesystem::exists(folder / "out" / "tablet.pvd"));
  EXPECT_TRUE(std::filesystem::exists(folder / "out" / "tablet_0020.pvtu"));
}

TEST_F(TabletApp, MalformedFrictionTableIsBadInput)
{
  write("bad.prm",
        "subsection Die\n  set Wall friction table = 0.9:0.2, 0.5:0.3\nend\n");
  expect_refused_without_output(compax("tablet bad.prm -o out"),
                                {"Wall friction table"});
}

TEST_F(TabletApp, StoppedRunResumesToTheUninterruptedResult)
{
  const std::string base
    = "subsection Mesh\n  set Radial cells = 4\nend\n"
      "subsection Process\n  set Compaction steps = 30\n"
      "  set Unloading steps = 8\n  set Ejection steps = 20\nend\n"
      "subsection Output\n  set Checkpoint interval = 10\n"
      "  set Write fields = false\nend\n";
  write("base.prm", base);
  // Too few Newton iterations for the first unloading step, which reverses
  // the wall friction: the run stops with exit code 3 and keeps its
  // checkpoint of step 30.
  write("stop.prm",
        base
          + "subsection Solver\n  set Max iterations = 8\n"
            "  set Max step cuts = 0\nend\n");
  write("resume.prm",
        base + "subsection Output\n  set Resume from = stopped\nend\n");
  ASSERT_EQ(compax("tablet base.prm -o full").exit_code, 0);
  const auto stopped = compax("tablet stop.prm -o stopped");
  ASSERT_EQ(stopped.exit_code, 3) << stopped.out;
  ASSERT_TRUE(
    std::filesystem::exists(folder / "stopped" / "checkpoint" / "tablet.h5"));
  const auto resumed = compax("tablet resume.prm -o resumed");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("Resuming after step 30"), std::string::npos);

  // Same binary, same partition, same Newton path: the resumed cycle
  // reproduces the uninterrupted one.
  const Csv full(folder / "full" / "tablet.csv");
  const Csv again(folder / "resumed" / "tablet.csv");
  expect_equal_rows(full,
                    again,
                    {"upper_punch_pressure",
                     "die_wall_pressure",
                     "ejection_force",
                     "mean_relative_density",
                     "mean_stress"},
                    0);

  // A checkpoint of another punch cycle is refused as bad input.
  write("other.prm",
        "subsection Mesh\n  set Radial cells = 4\nend\n"
        "subsection Output\n  set Resume from = stopped\nend\n");
  EXPECT_EQ(compax("tablet other.prm -o other").exit_code, 2);
}

TEST_F(TabletApp, MissingMeshFileIsBadInput)
{
  expect_prm_rejected(
    "tablet",
    "subsection Geometry\n  set Mesh file = no_such_mesh.msh\nend\n",
    "Mesh file");
}

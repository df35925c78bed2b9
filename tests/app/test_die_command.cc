// `compax die` through the real executable on a small bed: the columns the
// issue promises, force balance of the punches at every converged state (a
// frictionless die carries no axial load), the identities between the
// elastic-recovery measures of Eq. (16), the parameter list of fits.csv, and
// bad input.

#include "app_test_support.h"

#include "coupling/bed_archive.h"
#include "tests/support/gonzalez_material1.h"

#include <cmath>

using compax::testing::AppTest;
using compax::testing::Csv;
using compax::testing::expect_balanced_punches;
using compax::testing::expect_columns;

namespace
{
  const std::string small_bed = compax::testing::die_study_150();
}

class DieCommand : public AppTest
{
};

TEST_F(DieCommand, SmallBedCompactsUnloadsAndEjects)
{
  write("small.prm", small_bed);
  const auto r = compax("die small.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;

  const Csv die(folder / "out" / "die.csv");
  expect_columns(die,
                 {"stage",
                  "branch",
                  "relative_density",
                  "upper_punch_force",
                  "lower_punch_force",
                  "die_wall_force",
                  "coordination_number",
                  "bonding_surface",
                  "residual"});
  ASSERT_GT(die.rows(), 20u);

  expect_balanced_punches(die);

  // Eq. (16): eps_H = eps_rho / (1 - eps_rho) when the mass is fixed.
  const Csv branches(folder / "out" / "branches.csv");
  ASSERT_EQ(branches.rows(), 2u);
  for (std::size_t b = 0; b < 2; ++b)
    {
      const double e_rho = branches.column.at("elastic_recovery_rho")[b];
      EXPECT_GT(e_rho, 0.0);
      EXPECT_NEAR(branches.column.at("elastic_recovery_H")[b],
                  e_rho / (1 - e_rho),
                  1e-9);
      EXPECT_LT(branches.column.at("rho_min_in_die")[b],
                branches.column.at("rho_max_in_die")[b]);
    }

  const std::string  fits = read(folder / "out" / "fits.csv");
  std::string        names;
  std::istringstream lines(fits);
  for (std::string line; std::getline(lines, line);)
    names += line.substr(0, line.find(',')) + ' ';
  EXPECT_EQ(names,
            "parameter Z_c rho_c_Z theta K_p beta_p eps_0 rho_c_eps "
            "sigma_res_0 rho_c_e A_b0 rho_c_b E_0 n rho_c_E nu_tablet ");
}

TEST_F(DieCommand, ThinCompactUnloadsUntilThePunchComesFree)
{
  // 100 particles in a 4 mm die make a compact about one particle thick,
  // which unloads towards a stress-free state: the mean contact force
  // vanishes and a purely relative force criterion asks for round-off (the
  // run used to stop with exit 3 at the last unloading step).
  write("thin.prm",
        "subsection Packing\n set Number of particles = 100\n"
        " set Die diameter = 4e-3\nend\n"
        "subsection Protocol\n set Final relative density = 0.7\n"
        " set Unloading points = 0.7\n set Eject = false\nend\n");
  const auto r = compax("die thin.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;

  const Csv die(folder / "out" / "die.csv");
  expect_balanced_punches(die);
  // The punch comes free: the branch ends at the first state whose punch
  // force is below the force resolution (1e-2 x 0.5 MPa on pi R^2, R = 220
  // um), a force Z and Eq. (13) read as none. A balanced state may leave it a
  // round-off force (this bed's last row carried 3.3e-7 N when measured).
  const double resolution = 1e-2 * 0.5e6 * M_PI * 220e-6 * 220e-6;
  const auto  &stage      = die.text.at("stage");
  const auto  &force      = die.column.at("upper_punch_force");
  ASSERT_EQ(stage.back(), "unloading");
  EXPECT_LE(force.back(), resolution);
  for (std::size_t i = 0; i + 1 < stage.size(); ++i)
    {
      if (stage[i] == "unloading")
        {
          EXPECT_GT(force[i], resolution) << "row " << i;
        }
    }

  const Csv branches(folder / "out" / "branches.csv");
  ASSERT_EQ(branches.rows(), 1u);
  EXPECT_LT(branches.column.at("rho_min_in_die")[0],
            branches.column.at("rho_max_in_die")[0]);
}

TEST_F(DieCommand, UnloadingPointAboveFinalDensityIsRejected)
{
  write("bad.prm",
        "subsection Protocol\n set Final relative density = 0.8\n"
        " set Unloading points = 0.85\nend\n");
  const auto r = compax("die bad.prm -o out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("Unloading points"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0.85"), std::string::npos) << r.err;
  EXPECT_EQ(entries(), std::vector<std::string>{"bad.prm"});
}

TEST_F(DieCommand, DieNarrowerThanTwoParticlesIsRejected)
{
  write("bad.prm", "subsection Packing\n set Die diameter = 5e-4\nend\n");
  const auto r = compax("die bad.prm -o out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("Die diameter"), std::string::npos) << r.err;
  EXPECT_EQ(entries(), std::vector<std::string>{"bad.prm"});
}

TEST_F(DieCommand, NonConvergenceStopsCleanlyWithTheLastGoodState)
{
  // One Newton iteration per attempt cannot converge: the load step is cut
  // back, then the run stops with exit code 3, keeps the converged rows and
  // writes the state of the last one.
  write("stalls.prm",
        "subsection Packing\n set Number of particles = 150\n"
        " set Die diameter = 3e-3\nend\n"
        "subsection Solver\n set Maximum iterations = 1\nend\n");
  const auto r = compax("die stalls.prm -o out");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("last converged state"), std::string::npos) << r.err;

  const Csv die(folder / "out" / "die.csv");
  ASSERT_GE(die.rows(), 1u);
  const compax::coupling::Hdf5ArchiveReader archive(
    (folder / "out" / "last_converged.h5").string());
  const compax::dem::ContactModel model
    = compax::testing::material1::contact_model();
  const auto bed = compax::coupling::load_bed(archive, "bed", model);
  EXPECT_EQ(bed.particles.size(), 150u);
  EXPECT_NEAR(bed.relative_density(),
              die.column.at("relative_density").back(),
              1e-9);
}

TEST_F(DieCommand, BranchRerunFromItsCheckpointEqualsTheUninterruptedBranch)
{
  write("small.prm", small_bed);
  ASSERT_EQ(compax("die small.prm -o full").exit_code, 0);
  write("rerun.prm",
        "subsection Packing\n set Number of particles = 150\n"
        " set Die diameter = 3e-3\nend\n"
        "subsection Protocol\n"
        " set Rerun branch from = full/checkpoints/branch-2.h5\nend\n");
  const auto r = compax("die rerun.prm -o rerun");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv full(folder / "full" / "branches.csv");
  const Csv rerun(folder / "rerun" / "branches.csv");
  ASSERT_EQ(full.rows(), 2u);
  ASSERT_EQ(rerun.rows(), 1u);
  EXPECT_EQ(rerun.column.at("branch")[0], 2);
  for (const char *quantity : {"rho_max_in_die",
                               "rho_min_in_die",
                               "residual_radial_pressure",
                               "ejection_pressure",
                               "bonding_surface_unloaded"})
    EXPECT_NEAR(rerun.column.at(quantity)[0],
                full.column.at(quantity)[1],
                1e-9 * std::abs(full.column.at(quantity)[1]))
      << quantity;
}

/// A registered law runs in `compax die` through Contact/Contact law alone
/// (the Walton-Braun spring of the explicit-DEM peer, and the plastic
/// hardening law without elastic unloading): the punches balance at every
/// converged state and no solid bridge forms (neither law has one).
TEST_F(DieCommand, RegisteredLawsRunThroughTheRegistry)
{
  for (const std::string law : {"walton-braun", "plastic-hardening"})
    {
      SCOPED_TRACE(law);
      write("law.prm",
            small_bed + "subsection Contact\n  set Contact law = " + law
              + "\nend\n");
      const auto r = compax("die law.prm -o " + law);
      ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
      const Csv die(folder / law / "die.csv");
      ASSERT_GT(die.rows(), 20u);
      expect_balanced_punches(die);
      for (const double s : die.column.at("bonding_surface"))
        EXPECT_EQ(s, 0.0);
    }
}

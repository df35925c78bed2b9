// The RVE database study (coupling/rve_database_study): what it stores is
// what the cell it computed carries, and the errors it reports are those
// of the fitted table along the database's rows.
#include "coupling/rve_database_study.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_assembler.h"
#include "dem/rve/periodic_bed_system.h"
#include "dem/solver/trust_region_newton.h"
#include "fem/drucker_prager_cap.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace compax;

namespace
{
  /// 80 spheres, two branches: a few seconds.
  coupling::RveDatabaseStudyOptions
  small_study()
  {
    coupling::RveDatabaseStudyOptions o;
    o.spec.packing.particle_count = 80;
    o.spec.packing.seed           = 5;
    o.spec.final_density          = 0.76;
    o.spec.branch_densities       = {0.70, 0.76};
    o.spec.shear_steps            = 8;
    o.spec.radial_steps           = 4;
    o.spec.denser_deposit         = dem::DenserDeposit::keep;
    o.held_out_packing            = false;
    return o;
  }

  /// |s|^2 of a symmetric tensor in Voigt order (Frobenius).
  double
  norm2(const dem::Vector6d &s)
  {
    return s.head<3>().squaredNorm() + 2.0 * s.tail<3>().squaredNorm();
  }

  const coupling::DatabaseRow &
  compaction_row_at(const coupling::RveDatabase &db, const double density)
  {
    for (const coupling::DatabaseRow &r : db.rows)
      if (r.path == "compaction" && r.relative_density == density)
        return r;
    throw std::runtime_error("no compaction row at the branch density");
  }
} // namespace

/// At each branch the study hands out its compaction cell (for a
/// checkpoint). Its deformation is the stored compaction row's; the cell,
/// its particles disturbed by 1e-4 R and balanced again by an independent
/// Newton solve at that strain with frozen histories, carries the stored
/// stress to the solvers' tolerance: the database stores equilibria of
/// the cell at the strains it reports.
TEST(RveDatabaseStudy, StoredBranchStressIsTheCellsEquilibriumAtItsStrain)
{
  const dem::ContactModel model = compax::testing::material1::contact_model();
  coupling::RveDatabaseStudyOptions options = small_study();
  options.validate                          = false;
  coupling::RveDatabaseStudy    study(model, options);
  std::vector<dem::PeriodicBed> cells;
  int                           progress_lines = 0;
  study.on_branch_done
    = [&](const coupling::RveDatabase &, const dem::PeriodicBed &bed) {
        cells.push_back(bed);
      };
  study.on_progress = [&](const std::string &) { ++progress_lines; };
  const coupling::RveDatabaseStudyResult result = study.run();
  ASSERT_EQ(result.outcome, coupling::RveDatabaseOutcome::complete)
    << result.failure;
  EXPECT_GT(progress_lines, 0);
  ASSERT_EQ(result.database.branches.size(), 2u);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_EQ(result.fit.size(), 2u);
  EXPECT_FALSE(result.validation.law);

  dem::EquilibriumOptions tight = options.spec.loading.equilibrium;
  tight.force_tolerance         = 1e-7;
  tight.step_tolerance          = 1e-7;
  for (std::size_t k = 0; k < cells.size(); ++k)
    {
      const coupling::DatabaseBranch &branch = result.database.branches[k];
      const coupling::DatabaseRow    &row
        = compaction_row_at(result.database, branch.relative_density);
      dem::PeriodicBed &cell = cells[k];
      EXPECT_TRUE(cell.deformation.isApprox(row.deformation, 1e-14))
        << "branch " << k;
      const double scale = std::sqrt(norm2(row.stress));
      ASSERT_GT(scale, 1e6) << "branch " << k << " is jammed";
      EXPECT_LE(std::sqrt(norm2(branch.loaded_stress - row.stress)),
                1e-12 * scale);

      const double R = cell.particles.mean_radius();
      for (std::size_t i = 0; i < cell.particles.positions.size(); ++i)
        cell.particles.positions[i]
          += 1e-4 * R
             * Eigen::Vector3d(std::sin(1.0 + i), std::cos(2.0 * i), 0.5);
      dem::PeriodicAssembler       assembler;
      dem::PeriodicBedSystem       system(cell, model, assembler);
      const dem::EquilibriumResult solve
        = dem::TrustRegionNewton(tight).solve(system);
      ASSERT_TRUE(solve.converged)
        << "branch " << k << ": residual " << solve.relative_residual
        << " after " << solve.work.iterations << " iterations";
      const dem::Vector6d solved = dem::to_voigt(dem::love_weber_stress(cell));
      std::printf("branch %zu: |sigma| %.4g MPa, re-solved differs by %.2g\n",
                  k,
                  scale / 1e6,
                  std::sqrt(norm2(solved - row.stress)) / scale);
      // The stored state is balanced to the loading tolerance (1e-6 of
      // the mean contact force); the stress follows to about that.
      EXPECT_LE(std::sqrt(norm2(solved - row.stress)), 1e-5 * scale)
        << "branch " << k << ": stored " << row.stress.transpose()
        << ", solved " << solved.transpose();
    }
}

/// The reported training error is the pooled relative stress error of
/// the fitted table, driven along the database, over the training rows:
/// recomputed here from its definition (sum |d sigma|^2 / sum |sigma|^2),
/// it bounds every training row's error, and the fitted table is better
/// than no stress at all.
TEST(RveDatabaseStudy, ReportedTrainingErrorIsTheFittedTablesOnTheTrainingRows)
{
  const dem::ContactModel model = compax::testing::material1::contact_model();
  const coupling::RveDatabaseStudyResult result
    = coupling::RveDatabaseStudy(model, small_study()).run();
  ASSERT_EQ(result.outcome, coupling::RveDatabaseOutcome::complete)
    << result.failure;
  ASSERT_TRUE(result.validation.law);
  ASSERT_EQ(result.validation.comparisons.size(), 1u);
  const coupling::DatabaseComparison &fit = result.validation.comparisons[0];
  EXPECT_EQ(fit.name, "dpc_vs_rve");

  const fem::DruckerPragerCap      law(coupling::to_dpc_table(result.fit));
  const std::vector<dem::Vector6d> stress
    = coupling::drive_along_database(result.database, law);
  const auto &rows = result.database.rows;
  ASSERT_EQ(stress.size(), rows.size());
  double ds2 = 0.0, s2 = 0.0, worst = 0.0;
  for (std::size_t r = 0; r < rows.size(); ++r)
    {
      EXPECT_EQ(result.validation.law->rows[r].stress, stress[r]);
      if (!coupling::is_training_path(rows[r].path))
        continue;
      ds2 += norm2(stress[r] - rows[r].stress);
      s2 += norm2(rows[r].stress);
      worst = std::max(worst, norm2(stress[r] - rows[r].stress));
    }
  ASSERT_GT(s2, 0.0);
  EXPECT_NEAR(fit.training_error, std::sqrt(ds2 / s2), 1e-12);
  EXPECT_LE(std::sqrt(worst), fit.training_error * std::sqrt(s2));
  EXPECT_GT(fit.training_error, 0.0);
  EXPECT_LT(fit.training_error, 1.0);
  std::printf("training error %.3f, held-out radial probes %.3f\n",
              fit.training_error,
              fit.held_out_error);
}

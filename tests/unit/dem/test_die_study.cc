// The die study as a library class (dem::DieStudy): its converged states
// balance the punches (the die wall is frictionless and there is no
// gravity, so it carries no axial load), its observer sees every converged
// row as it is computed, and a study resumed from a checkpoint it handed
// out gives the rows of the uninterrupted run.

#include "dem/die/die_study.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace compax::dem;

namespace
{
  ContactModel
  material1()
  {
    return compax::testing::material1::contact_model();
  }

  /// 120 spheres in a 3 mm die to rho = 0.78 in 12 steps, branches at 0.70
  /// and 0.78 (13 compaction targets), a checkpoint every 3 targets.
  DieStudyOptions
  small_study()
  {
    DieStudyOptions o;
    o.deposition.n_particles       = 120;
    o.deposition.die_diameter      = 3e-3;
    o.deposition.seed              = 5;
    o.final_density                = 0.78;
    o.compaction_steps             = 12;
    o.protocol.unloading_points    = {0.7, 0.78};
    o.protocol.checkpoint_interval = 3;
    return o;
  }

  /// What an observer saw.
  struct Seen
  {
    std::vector<DieRecord>   rows;
    std::vector<std::string> branch_states;
    std::vector<std::string> lines;
    /// The last checkpoint handed out, and how many there were.
    std::optional<Bed>         bed;
    std::optional<DieProgress> progress;
    int                        checkpoints = 0;

    DieStudyObserver
    observer()
    {
      DieStudyObserver o;
      o.row      = [this](const DieRecord &r) { rows.push_back(r); };
      o.progress = [this](const std::string &l) { lines.push_back(l); };
      o.branch_state
        = [this](const Bed &, const std::string &stage, const int branch) {
            branch_states.push_back(stage + "-" + std::to_string(branch));
          };
      o.checkpoint = [this](const Bed &b, const DieProgress &p) {
        bed      = b;
        progress = p;
        ++checkpoints;
      };
      return o;
    }
  };

  /// Every number of a die.csv row (the wall time aside) is the same.
  void
  expect_same_row(const DieRecord &a, const DieRecord &b, const std::size_t i)
  {
    EXPECT_EQ(a.stage, b.stage) << "row " << i;
    EXPECT_EQ(a.branch, b.branch) << "row " << i;
    EXPECT_EQ(a.step, b.step) << "row " << i;
    for (const auto member : {&DieRecord::punch_gap,
                              &DieRecord::relative_density,
                              &DieRecord::rho_min_in_die,
                              &DieRecord::rho_tablet,
                              &DieRecord::upper_punch_force,
                              &DieRecord::lower_punch_force,
                              &DieRecord::die_wall_force,
                              &DieRecord::coordination_number,
                              &DieRecord::bonding_surface,
                              &DieRecord::residual_radial_pressure,
                              &DieRecord::ejection_pressure,
                              &DieRecord::residual,
                              &DieRecord::sigma_zz_interior})
      {
        const double x = a.*member, y = b.*member;
        if (std::isnan(x))
          EXPECT_TRUE(std::isnan(y)) << "row " << i;
        else
          EXPECT_EQ(x, y) << "row " << i;
      }
    EXPECT_EQ(a.bonds, b.bonds) << "row " << i;
    EXPECT_EQ(a.iterations, b.iterations) << "row " << i;
  }
} // namespace

TEST(DieStudy, ConvergedStatesBalanceThePunchesAndReachTheObserver)
{
  // Newton to 1e-9 of the mean contact force: the punches then balance to
  // well below 1e-6 of their load.
  DieStudyOptions options             = small_study();
  options.equilibrium.force_tolerance = 1e-9;
  Seen                 seen;
  DieStudy             study(material1(), options);
  const DieStudyResult r = study.run(seen.observer());
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_FALSE(r.stopped);
  EXPECT_EQ(r.taken_over, 0u);

  // The observer saw every converged state, in order, as the result has it.
  ASSERT_EQ(seen.rows.size(), r.rows.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    expect_same_row(seen.rows[i], r.rows[i], i);
  // The deposit and 13 compaction targets: 12 steps to 0.78 and the
  // unloading point 0.70 between them.
  std::size_t compaction = 0;
  for (const auto &row : r.rows)
    compaction += row.stage == "compaction";
  EXPECT_EQ(compaction, 14u);
  ASSERT_EQ(r.branches.size(), 2u);
  EXPECT_EQ(seen.branch_states,
            (std::vector<std::string>{"compaction-1",
                                      "unloading-1",
                                      "ejection-1",
                                      "compaction-2",
                                      "unloading-2",
                                      "ejection-2"}));
  // After 3, 6, 9 and 12 of the 13 targets, and once at the end.
  EXPECT_EQ(seen.checkpoints, 5);
  EXPECT_FALSE(seen.lines.empty());
  EXPECT_EQ(r.fits.branches, 2u);

  // No gravity, frictionless die wall: the punches carry the same axial
  // force, up to the particles' residual forces (at most N times the
  // largest, relative residual x mean contact force).
  const double n      = double(study.options().deposition.n_particles);
  std::size_t  jammed = 0;
  double       worst  = 0.0;
  for (const auto &row : r.rows)
    {
      if (row.stage == "ejection"
          || row.upper_punch_pressure <= r.pressure_resolution)
        continue;
      const double imbalance
        = std::abs(row.upper_punch_force - row.lower_punch_force);
      EXPECT_LE(imbalance,
                n * row.residual * row.mean_contact_force
                  + 1e-12 * row.upper_punch_force)
        << row.stage << " " << row.branch << " " << row.step;
      if (row.relaxed == 0)
        {
          ++jammed;
          worst = std::max(worst, imbalance / row.upper_punch_force);
        }
    }
  EXPECT_GE(jammed, 5u);
  // Newton's states: to the force tolerance, far below 1e-6 of the load.
  EXPECT_LT(worst, 1e-6);
}

TEST(DieStudy, ResumedFromACheckpointGivesTheRowsOfTheUninterruptedRun)
{
  Seen                 full_seen;
  const DieStudyResult full
    = DieStudy(material1(), small_study()).run(full_seen.observer());
  ASSERT_TRUE(full.converged) << full.failure;

  // Stop after 12 of 13 targets (a checkpoint the uninterrupted run hands
  // out too), past branch 1.
  DieStudyOptions stopping     = small_study();
  stopping.protocol.stop_after = 12;
  Seen                 first_seen;
  const DieStudyResult first
    = DieStudy(material1(), stopping).run(first_seen.observer());
  ASSERT_TRUE(first.stopped);
  ASSERT_TRUE(first_seen.progress.has_value());
  EXPECT_EQ(first_seen.progress->completed_targets, 12u);
  EXPECT_EQ(first_seen.progress->branches_run, 1);

  DieStudy resumed(material1(),
                   small_study(),
                   DieStudyStart::resume(*first_seen.bed,
                                         *first_seen.progress));
  EXPECT_EQ(resumed.resume_mismatch(), "");
  Seen                 second_seen;
  const DieStudyResult second = resumed.run(second_seen.observer());
  ASSERT_TRUE(second.converged) << second.failure;
  EXPECT_EQ(second.taken_over, first.rows.size());
  // The observer sees the new rows only.
  EXPECT_EQ(second_seen.rows.size(), second.rows.size() - second.taken_over);

  ASSERT_EQ(second.rows.size(), full.rows.size());
  for (std::size_t i = 0; i < full.rows.size(); ++i)
    expect_same_row(full.rows[i], second.rows[i], i);
  ASSERT_EQ(second.branches.size(), full.branches.size());
  for (std::size_t k = 0; k < full.branches.size(); ++k)
    {
      EXPECT_EQ(second.branches[k].rho_min_in_die,
                full.branches[k].rho_min_in_die);
      EXPECT_EQ(second.branches[k].residual_radial_pressure,
                full.branches[k].residual_radial_pressure);
      EXPECT_EQ(second.branches[k].rho_tablet, full.branches[k].rho_tablet);
    }
}

TEST(DieStudy, ProgressOfOtherTargetsIsRefused)
{
  Seen            seen;
  DieStudyOptions stopping     = small_study();
  stopping.protocol.stop_after = 4;
  DieStudy(material1(), stopping).run(seen.observer());
  ASSERT_TRUE(seen.progress.has_value());
  // Twice the compaction steps: the targets done differ.
  DieStudyOptions other  = small_study();
  other.compaction_steps = 24;
  DieStudy study(material1(),
                 other,
                 DieStudyStart::resume(*seen.bed, *seen.progress));
  EXPECT_NE(study.resume_mismatch(), "");
  EXPECT_THROW(study.run(), std::invalid_argument);
}

TEST(DieStudy, FinalDensityBelowThePackingIsRefused)
{
  DieStudyOptions o = small_study();
  o.final_density   = 0.3;
  EXPECT_THROW(DieStudy(material1(), o).run(), DieTargetError);
  EXPECT_THROW(die_compaction_targets(0.6, 0.6, 10), DieTargetError);
  EXPECT_EQ(die_compaction_targets(0.6, 0.8, 4).size(), 4u);
}

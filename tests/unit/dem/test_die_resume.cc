// Resuming the die protocol from a checkpoint (the bed on the compaction
// path and the DieProgress handed to on_checkpoint) retraces the
// uninterrupted run: the same rows and branch results. A progress whose
// completed targets differ from the protocol's is refused.

#include "dem/die/die_compaction.h"
#include "dem/die/die_setup.h"
#include "tests/support/deposited_die.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <sstream>

using namespace compax::dem;

namespace
{
  struct Study
  {
    Bed          bed;
    ContactModel model = compax::testing::material1::contact_model();
    DieProtocol  protocol;
  };

  Study
  small_study()
  {
    Study s;
    s.bed = compax::testing::deposited_die(120, 3e-3, 5);
    s.protocol.compaction_targets
      = density_targets(s.bed.relative_density(), 0.78, 12);
    s.protocol.unloading_points    = {0.7, 0.78};
    s.protocol.checkpoint_interval = 3;
    return s;
  }
} // namespace

TEST(DieResume, ResumedRunRetracesTheUninterruptedRun)
{
  Study         s = small_study();
  DieCompaction full(s.bed, s.model, s.protocol);
  // Keep the last checkpoint: after 12 of the 13 targets, past branch 1.
  std::optional<Bed>         saved_bed;
  std::optional<DieProgress> saved;
  full.on_checkpoint = [&](const Bed &b, const DieProgress &p) {
    saved_bed = b;
    saved     = p;
  };
  ASSERT_NO_THROW(full.run());
  ASSERT_TRUE(saved.has_value());
  ASSERT_EQ(saved->completed_targets, 12u);
  ASSERT_EQ(saved->branches_run, 1);
  ASSERT_EQ(full.branches().size(), 2u);

  DieCompaction      resumed(*saved_bed, s.model, s.protocol);
  std::ostringstream csv;
  resumed.set_output(&csv, nullptr);
  ASSERT_NO_THROW(resumed.resume(*saved));

  const auto &a = full.records();
  const auto &b = resumed.records();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    {
      EXPECT_EQ(a[i].stage, b[i].stage);
      EXPECT_NEAR(a[i].relative_density, b[i].relative_density, 1e-12);
      EXPECT_NEAR(a[i].upper_punch_force,
                  b[i].upper_punch_force,
                  1e-9 * std::abs(a[i].upper_punch_force) + 1e-300)
        << "row " << i;
      EXPECT_NEAR(a[i].die_wall_force,
                  b[i].die_wall_force,
                  1e-9 * std::abs(a[i].die_wall_force) + 1e-300)
        << "row " << i;
      EXPECT_EQ(a[i].bonds, b[i].bonds);
    }
  ASSERT_EQ(resumed.branches().size(), 2u);
  const BranchSummary &x = full.branches()[1], &y = resumed.branches()[1];
  EXPECT_NEAR(x.rho_min_in_die, y.rho_min_in_die, 1e-9 * x.rho_min_in_die);
  EXPECT_NEAR(x.residual_radial_pressure,
              y.residual_radial_pressure,
              1e-9 * x.residual_radial_pressure);
  // The CSV got the earlier rows too: header + every row.
  std::size_t lines = 0;
  for (const char c : csv.str())
    lines += c == '\n';
  EXPECT_EQ(lines, b.size() + 1);
}

TEST(DieResume, ProgressOfOtherTargetsIsRefused)
{
  Study       s = small_study();
  DieProgress p;
  p.compaction_targets = s.protocol.compaction_targets;
  p.compaction_targets[0] += 0.01;
  p.completed_targets = 2;
  p.rows.resize(1);
  DieCompaction die(s.bed, s.model, s.protocol);
  EXPECT_THROW(die.resume(p), std::invalid_argument);
}

/// An unloading branch (with its ejection) steps with a stepper of its own:
/// the compaction path through the same targets is bit for bit the same
/// whether or not the branch is taken. (With one stepper shared, the
/// branch's sub-step and predictor memory would carry into the next
/// compaction step and move its converged state within the tolerance.)
TEST(DieResume, CompactionPathDoesNotDependOnTheBranchesTaken)
{
  Study s                        = small_study();
  s.protocol.checkpoint_interval = 0;
  s.protocol.unloading_points    = {0.7};
  s.protocol.eject               = true;
  DieProtocol without            = s.protocol;
  without.unloading_points.clear();
  without.compaction_targets.push_back(0.7);
  std::sort(without.compaction_targets.begin(),
            without.compaction_targets.end());

  DieCompaction with_branch(s.bed, s.model, s.protocol);
  DieCompaction no_branch(s.bed, s.model, without);
  ASSERT_NO_THROW(with_branch.run());
  ASSERT_NO_THROW(no_branch.run());
  ASSERT_EQ(with_branch.branches().size(), 1u);
  ASSERT_TRUE(no_branch.branches().empty());

  std::vector<DieRecord> a, b;
  for (const DieRecord &r : with_branch.records())
    if (r.stage == "compaction")
      a.push_back(r);
  for (const DieRecord &r : no_branch.records())
    if (r.stage == "compaction")
      b.push_back(r);
  ASSERT_EQ(a.size(), b.size());
  // Some compaction steps follow the branch.
  ASSERT_LT(with_branch.branches()[0].rho_max_in_die + 0.05,
            a.back().relative_density);
  for (std::size_t i = 0; i < a.size(); ++i)
    {
      EXPECT_EQ(a[i].relative_density, b[i].relative_density) << "row " << i;
      EXPECT_EQ(a[i].upper_punch_force, b[i].upper_punch_force) << "row " << i;
      EXPECT_EQ(a[i].die_wall_force, b[i].die_wall_force) << "row " << i;
      EXPECT_EQ(a[i].bonds, b[i].bonds) << "row " << i;
    }
}

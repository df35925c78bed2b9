#include "dem/die/die_compaction.h"
#include "dem/die/die_setup.h"
#include "tests/support/walton_braun_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

using namespace compax::dem;

namespace
{
  /// What a die run leaves: its records and its final bed.
  struct DieRun
  {
    std::vector<DieRecord> records;
    Bed                    bed;
  };

  /// A deposit of 120 spheres in a 3 mm die compacted to 0.72 and unloaded
  /// there, without ejection.
  DieRun
  compacted(const ContactModel &model,
            const bool          relax_opening_at_first_failure = true)
  {
    DepositionParameters dp;
    dp.n_particles  = 120;
    dp.die_diameter = 3e-3;
    dp.seed         = 4;
    const Bed   bed = fill_die(dp);
    DieProtocol protocol;
    protocol.compaction_targets
      = density_targets(bed.relative_density(), 0.72, 16);
    protocol.unloading_points               = {0.72};
    protocol.eject                          = false;
    protocol.relax_opening_at_first_failure = relax_opening_at_first_failure;
    DieCompaction die(bed, model, protocol);
    die.run();
    return {die.records(), die.bed()};
  }

  /// |F_u - F_l| of a record [N].
  double
  punch_imbalance(const DieRecord &r)
  {
    return std::abs(r.upper_punch_force - r.lower_punch_force);
  }

  /// A frictionless die wall carries no axial force, so the punches differ
  /// by at most N times the largest particle residual of the state.
  double
  imbalance_bound(const DieRun &run, const DieRecord &r)
  {
    return run.bed.particles.size() * r.residual * r.mean_contact_force
           + 1e-12 * std::abs(r.upper_punch_force);
  }

  /// Cut-backs and relaxed rows of a run's unloading.
  struct UnloadingWork
  {
    int cutbacks = 0;
    int relaxed  = 0;
  };

  UnloadingWork
  unloading_work(const DieRun &run)
  {
    UnloadingWork w;
    for (const DieRecord &r : run.records)
      if (r.stage == "unloading")
        {
          w.cutbacks += r.cutbacks;
          w.relaxed += r.relaxed;
        }
    return w;
  }

  /// Elastic recovery eps_rho = (rho_max - rho_min) / rho_max of the
  /// unloading branch (Gonzalez 2018, Eq. 16), from its last record.
  double
  elastic_recovery(const std::vector<DieRecord> &records)
  {
    for (auto r = records.rbegin(); r != records.rend(); ++r)
      if (r->stage == "unloading")
        return r->elastic_recovery_rho;
    return NAN;
  }
} // namespace

/// The particle solver holds the registered law in every contact, pairs
/// and walls, and the punches balance at every converged state (frictionless
/// die wall: F_u - F_l is bounded by N times the largest particle residual).
TEST(WaltonBraunDie, EveryContactFollowsTheLawAndThePunchesBalance)
{
  const DieRun die = compacted(compax::testing::walton_braun_model(22.0));
  ASSERT_FALSE(die.bed.contacts.pairs.empty());
  for (const PairContact &c : die.bed.contacts.pairs)
    ASSERT_TRUE(std::holds_alternative<WaltonBraunLaw>(c.law));
  for (const WallContact &c : die.bed.contacts.walls)
    ASSERT_TRUE(std::holds_alternative<WaltonBraunLaw>(c.law));
  for (const DieRecord &r : die.records)
    {
      if (r.stage == "compaction" && r.step == 0)
        continue; // the deposit
      EXPECT_LE(punch_imbalance(r), imbalance_bound(die, r))
        << r.stage << " step " << r.step;
    }
}

/// The converged states commit delta_max, so unloading follows the stiffer
/// branch. With phi_F = 0 every contact un/reloads with k2 = k2_max: a
/// contact loaded to delta_max recovers delta_max k1/k2_max of its overlap
/// before it carries no force, so with k2_max = 22 k1 the bed recovers
/// about 1/22 of what it recovers with k2_max = k1 (a reversible spring
/// whose punch comes free only near the jamming density). The bound of 1/5
/// leaves room for the non-affine relaxation of the bed. Every contact
/// ends below its committed largest overlap.
TEST(WaltonBraunDie, ElasticRecoveryFollowsTheCommittedUnloadingStiffness)
{
  const DieRun stiff
    = compacted(compax::testing::walton_braun_model(22.0, 0.0));
  const DieRun elastic
    = compacted(compax::testing::walton_braun_model(1.0, 0.0));
  const double eps_22 = elastic_recovery(stiff.records);
  const double eps_1  = elastic_recovery(elastic.records);
  EXPECT_GT(eps_22, 0.0);
  EXPECT_LT(eps_22, 0.2 * eps_1) << "k2 = k1 recovers " << eps_1;
  for (const PairContact &c : stiff.bed.contacts.pairs)
    EXPECT_LE(pair_overlap(stiff.bed.particles, c),
              WaltonBraunLaw::delta_max(c.history));
}

/// A compact without adhesion comes apart on unloading: its network turns
/// hypostatic before the punch carries nothing, and Newton fails there.
/// With Opening fallback = after-cutbacks such a step is cut back down to
/// the smallest sub-step before the balanced relaxation takes it; with
/// at-first-failure (the default) the relaxation takes it without a
/// cut-back. The compaction path is the same to the bit (the option acts on
/// opening steps only), and every unloading state balances its punches.
TEST(WaltonBraunDie, AnOpeningStepNewtonCannotBalanceIsRelaxedAtOnce)
{
  const ContactModel  model = compax::testing::walton_braun_model(22.0);
  const DieRun        after_cutbacks   = compacted(model, false);
  const DieRun        at_first_failure = compacted(model, true);
  const UnloadingWork after            = unloading_work(after_cutbacks);
  const UnloadingWork early            = unloading_work(at_first_failure);
  ASSERT_GT(after.relaxed, 0) << "the bed does not come apart here";
  EXPECT_GT(after.cutbacks, 0) << after.relaxed << " relaxed rows";
  EXPECT_GT(early.relaxed, 0);
  EXPECT_EQ(early.cutbacks, 0);
  const std::size_t n
    = std::min(after_cutbacks.records.size(), at_first_failure.records.size());
  for (std::size_t i = 0; i < n; ++i)
    {
      const DieRecord &a = after_cutbacks.records[i];
      const DieRecord &b = at_first_failure.records[i];
      if (a.stage != "compaction")
        break;
      EXPECT_EQ(a.upper_punch_force, b.upper_punch_force) << "step " << a.step;
    }
  for (const DieRecord &r : at_first_failure.records)
    if (r.stage == "unloading")
      {
        EXPECT_LE(punch_imbalance(r), imbalance_bound(at_first_failure, r))
          << "unloading step " << r.step;
      }
}

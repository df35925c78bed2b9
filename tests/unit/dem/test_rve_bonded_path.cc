/// The periodic RVE's bonded path below its jamming pressure (issue #15):
/// the die's rules (Eq. 13 on relaxed states, cut-back of failed
/// sub-steps, sticky jamming) on a deposit-like cell.
#include "dem/rve/deposited_packing.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_assembler.h"
#include "dem/rve/rve_loading.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace compax::dem;
namespace material1 = compax::testing::material1;
using material1::R;

namespace
{
  PeriodicBed
  deposited_cell()
  {
    DepositedPackingSpec spec;
    spec.particle_count      = 120;
    spec.sizes.median_radius = R;
    spec.seed                = 5;
    return make_deposited_packing(spec);
  }

  Eigen::Matrix3d
  axial(const double eps_zz)
  {
    Eigen::Matrix3d e = Eigen::Matrix3d::Zero();
    e(2, 2)           = eps_zz;
    return e;
  }

  struct HistoryCount
  {
    int plastic = 0; // contacts with a_p > 0
    int bridges = 0; // contacts with a_B > 0
  };

  HistoryCount
  count_histories(const PeriodicBed &bed)
  {
    HistoryCount n;
    for (const PeriodicContact &c : bed.contacts.pairs)
      {
        n.plastic += BondedElastoplasticLaw::a_p(c.history) > 0.0;
        n.bridges += BondedElastoplasticLaw::a_B(c.history) > 0.0;
      }
    return n;
  }

  std::vector<ContactHistory>
  histories(const PeriodicBed &bed)
  {
    std::vector<ContactHistory> h;
    for (const PeriodicContact &c : bed.contacts.pairs)
      h.push_back(c.history);
    return h;
  }

  /// Every contact of @p bed still has the a_p and a_B of @p before (the
  /// histories taken before a failed sub-step).
  void
  expect_histories_unchanged(const PeriodicBed                 &bed,
                             const std::vector<ContactHistory> &before)
  {
    const auto after = histories(bed);
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t c = 0; c < after.size(); ++c)
      {
        EXPECT_EQ(BondedElastoplasticLaw::a_p(after[c]),
                  BondedElastoplasticLaw::a_p(before[c]));
        EXPECT_EQ(BondedElastoplasticLaw::a_B(after[c]),
                  BondedElastoplasticLaw::a_B(before[c]));
      }
  }

  RveLoadingOptions
  options(const RveConsolidation consolidation)
  {
    RveLoadingOptions o;
    o.consolidation = consolidation;
    return o;
  }

  constexpr double step = -2e-3; // axial logarithmic strain per step [-]
} // namespace

/// Below the jamming pressure the bonded path commits the relaxed states
/// with Eq. (13): contacts whose force exceeds the force resolution grow a
/// plastic radius (and a bridge). The frozen-history path, driven through
/// the very same strains, leaves every contact virgin. Both stay in
/// equilibrium to the relaxation's tolerance or the force resolution.
TEST(RveBondedPath, UnjammedRelaxationsCommitHistoriesFrozenDoNot)
{
  const ContactModel model  = material1::contact_model();
  PeriodicBed        bonded = deposited_cell();
  PeriodicBed        frozen = bonded;
  RveLoading         bonded_loading(model, options(RveConsolidation::none));
  RveLoading   frozen_loading(model, options(RveConsolidation::frozen_history));
  const double p_jam      = bonded_loading.options().jamming_pressure;
  const double resolution = bonded_loading.force_resolution(bonded);
  // pi R^2 p_jam / 100, the die's force resolution.
  EXPECT_NEAR(resolution, 1e-2 * p_jam * M_PI * R * R, 1e-12 * resolution);

  bool committed = false;
  for (int k = 0; k < 200 && !committed; ++k)
    {
      const RveStepResult b = bonded_loading.apply_strain(bonded, axial(step));
      ASSERT_TRUE(b.converged) << "step " << k;
      if (!b.relaxed)
        break; // jammed before any history grew: the test proves nothing
      const RveStepResult f = frozen_loading.apply_strain(frozen, axial(step));
      ASSERT_TRUE(f.converged) << "step " << k;
      ASSERT_TRUE(f.relaxed);
      const HistoryCount n = count_histories(bonded);
      committed            = n.plastic > 0 || n.bridges > 0;
    }
  ASSERT_TRUE(committed) << "no history grew below jamming";
  // Still below jamming, at the same macroscopic strain.
  EXPECT_LT(mean_pressure(bonded), p_jam);
  EXPECT_EQ(bonded.deformation, frozen.deformation);
  const HistoryCount n = count_histories(frozen);
  EXPECT_EQ(n.plastic, 0);
  EXPECT_EQ(n.bridges, 0);

  // The committed state is a relaxed equilibrium: every net force within
  // the relaxation's tolerance of the mean contact force, or below the
  // force resolution.
  PeriodicAssembler assembler;
  Eigen::VectorXd   F;
  const ContactSums sums  = assembler.residual(bonded, model, F);
  const double      worst = max_particle_norm(F);
  EXPECT_TRUE(worst <= 1.0001 * resolution
              || worst <= 1.0001 * bonded_loading.options().fire_tolerance
                            * sums.mean_force)
    << worst;
}

/// A sub-step that cannot converge, relaxed or solved by Newton, leaves
/// every particle and every a_p, a_B as they were.
TEST(RveBondedPath, FailedSubstepLeavesHistoriesUntouched)
{
  const ContactModel model = material1::contact_model();
  PeriodicBed        bed   = deposited_cell();
  RveLoading         loading(model, options(RveConsolidation::none));
  // Compact until some history exists, then on into jamming.
  bool loose_with_history = false, jammed = false;
  for (int k = 0; k < 300 && !jammed; ++k)
    {
      const RveStepResult r = loading.apply_strain(bed, axial(step));
      ASSERT_TRUE(r.converged) << "step " << k;
      jammed = r.jammed;
      if (r.relaxed && count_histories(bed).plastic > 0 && !loose_with_history)
        {
          loose_with_history = true;
          // An unjammed relaxation with 2 FIRE iterations fails.
          RveLoadingOptions o   = options(RveConsolidation::none);
          o.fire_iterations     = 2;
          o.balanced_iterations = 2;
          // ... and so does Newton, should the cell jam on the way.
          o.equilibrium.max_iterations  = 1;
          o.equilibrium.fire_iterations = 0;
          o.stepping.min_fraction       = 0.25;
          RveLoading  failing(model, o);
          PeriodicBed copy   = bed;
          const auto  before = histories(copy);
          const auto  x      = copy.particles.positions;
          ASSERT_FALSE(failing.jammed(copy));
          const RveStepResult f = failing.apply_strain(copy, axial(-2e-2));
          EXPECT_FALSE(f.converged);
          EXPECT_GT(f.cutbacks, 0);
          EXPECT_EQ(copy.particles.positions, x);
          ASSERT_NO_FATAL_FAILURE(expect_histories_unchanged(copy, before));
        }
    }
  ASSERT_TRUE(loose_with_history);
  ASSERT_TRUE(jammed);
  const HistoryCount n = count_histories(bed);
  ASSERT_GT(n.plastic, 0);
  ASSERT_GT(n.bridges, 0);

  // A jammed cell whose Newton solve gets one iteration per sub-step.
  RveLoadingOptions o          = options(RveConsolidation::none);
  o.equilibrium.max_iterations = 1;
  o.stepping.min_fraction      = 0.25;
  RveLoading failing(model, o);
  const auto before = histories(bed);
  const auto x      = bed.particles.positions;
  ASSERT_TRUE(failing.jammed(bed));
  const RveStepResult f = failing.apply_strain(bed, axial(-2e-2));
  EXPECT_FALSE(f.converged);
  EXPECT_EQ(bed.particles.positions, x);
  ASSERT_NO_FATAL_FAILURE(expect_histories_unchanged(bed, before));
}

/// Once a converged state carried the jamming pressure the cell is a
/// solid: unloading steps are Newton solves even where the mean pressure
/// has fallen below the jamming pressure. The frozen-history path relaxes
/// such a step by FIRE instead.
TEST(RveBondedPath, JammingIsSticky)
{
  const ContactModel model = material1::contact_model();
  PeriodicBed        bed   = deposited_cell();
  RveLoading         loading(model, options(RveConsolidation::none));
  const double       p_jam = loading.options().jamming_pressure;
  ASSERT_FALSE(loading.jammed(bed));
  bool jammed = false;
  for (int k = 0; k < 300 && !jammed; ++k)
    {
      const RveStepResult r = loading.apply_strain(bed, axial(step));
      ASSERT_TRUE(r.converged) << "step " << k;
      jammed = r.jammed;
      // Jammed exactly when the converged state carries the pressure.
      EXPECT_EQ(jammed, mean_pressure(bed) >= p_jam);
    }
  ASSERT_TRUE(jammed);
  // Compact a little further, then unload until the mean pressure is well
  // below the jamming pressure.
  for (int k = 0; k < 5; ++k)
    ASSERT_TRUE(loading.apply_strain(bed, axial(step)).converged);
  bool        below = false;
  PeriodicBed below_state;
  for (int k = 0; k < 200 && !below; ++k)
    {
      const RveStepResult r = loading.apply_strain(bed, axial(5e-4));
      ASSERT_TRUE(r.converged) << "unloading step " << k;
      EXPECT_FALSE(r.relaxed) << "unloading step " << k;
      EXPECT_TRUE(r.jammed);
      EXPECT_TRUE(loading.jammed(bed));
      below = mean_pressure(bed) < 0.5 * p_jam;
    }
  ASSERT_TRUE(below);
  // Below jamming, one more unloading step is still solved by Newton, and
  // the solution is Newton's equilibrium (EquilibriumOptions tolerance).
  below_state           = bed;
  const RveStepResult r = loading.apply_strain(bed, axial(5e-4));
  ASSERT_TRUE(r.converged);
  EXPECT_FALSE(r.relaxed);
  EXPECT_GT(r.iterations, 0);
  EXPECT_EQ(r.relaxation_iterations, 0);
  PeriodicAssembler assembler;
  Eigen::VectorXd   F;
  const ContactSums sums = assembler.residual(bed, model, F);
  EXPECT_LE(max_particle_norm(F),
            std::max(1.0000001 * loading.options().equilibrium.force_tolerance
                       * sums.mean_force,
                     loading.options().equilibrium.force_floor));

  // The frozen-history path from the same state relaxes by FIRE.
  RveLoading frozen(model, options(RveConsolidation::frozen_history));
  EXPECT_FALSE(frozen.jammed(below_state));
  const RveStepResult f = frozen.apply_strain(below_state, axial(5e-4));
  ASSERT_TRUE(f.converged);
  EXPECT_TRUE(f.relaxed);
  EXPECT_GT(f.relaxation_iterations, 0);
}

namespace
{
  /// Compacts the deposited cell uniaxially until it jams with the given
  /// unjammed equilibrium; every converged loose state must be balanced to
  /// the equilibrium tolerance, checked by an independent residual: every
  /// net force within force_tolerance of the mean contact force or below
  /// the loading's balanced force floor. Returns the relaxed flags.
  std::vector<bool>
  expect_loose_states_balanced(const UnjammedEquilibrium unjammed)
  {
    const ContactModel model  = material1::contact_model();
    PeriodicBed        bed    = deposited_cell();
    RveLoadingOptions  opts   = options(RveConsolidation::none);
    opts.unjammed_equilibrium = unjammed;
    RveLoading        loading(model, opts);
    const double      tol   = opts.equilibrium.force_tolerance;
    const double      floor = loading.balanced_force_floor(bed);
    std::vector<bool> relaxed;
    for (int k = 0; k < 200 && !loading.jammed(bed); ++k)
      {
        const RveStepResult r = loading.apply_strain(bed, axial(step));
        EXPECT_TRUE(r.converged) << "step " << k;
        if (!r.converged)
          break;
        PeriodicAssembler assembler;
        Eigen::VectorXd   F;
        const ContactSums sums  = assembler.residual(bed, model, F);
        const double      worst = max_particle_norm(F);
        EXPECT_TRUE(worst <= 1.0001 * tol * sums.mean_force
                    || worst <= 1.0001 * floor)
          << "step " << k << ": " << worst << " N";
        if (!loading.jammed(bed))
          relaxed.push_back(r.relaxed);
      }
    EXPECT_GT(relaxed.size(), 5u); // the path had loose states to balance
    EXPECT_TRUE(loading.jammed(bed));
    return relaxed;
  }
} // namespace

/// With Newton after each unjammed relaxation, every converged loose state
/// is a Newton solution (not a relaxed state).
TEST(RveBondedPath, NewtonAfterRelaxationBalancesLooseStates)
{
  for (const bool relaxed : expect_loose_states_balanced(
         UnjammedEquilibrium::relaxation_then_newton))
    EXPECT_FALSE(relaxed);
}

/// A balanced relaxation balances the loose states itself.
TEST(RveBondedPath, BalancedRelaxationBalancesLooseStates)
{
  for (const bool relaxed :
       expect_loose_states_balanced(UnjammedEquilibrium::balanced_relaxation))
    EXPECT_TRUE(relaxed);
}

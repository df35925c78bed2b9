#include "dem/die/die_compaction.h"
#include "dem/die/die_setup.h"
#include "dem/numbers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

using namespace compax::dem;

namespace
{
  /// A deposit of @p n spheres in a 3 mm die, the beds of these tests.
  Bed
  deposit(const std::size_t n, const unsigned int seed)
  {
    DepositionParameters dp;
    dp.n_particles  = n;
    dp.die_diameter = 3e-3;
    dp.seed         = seed;
    return fill_die(dp);
  }

  /// Material 1 of Gonzalez 2018 (Table 1) with its bonds.
  ContactModel
  material1()
  {
    return ContactModel(ElastoplasticMaterial{5e9, 0.25, 150e6, 2.0}, 1.26e6);
  }

  /// The jammed path of these tests: @p bed compacted to rho = 0.8 in 20
  /// steps.
  DieProtocol
  compaction_to_080(const Bed &bed)
  {
    DieProtocol protocol;
    protocol.compaction_targets
      = density_targets(bed.relative_density(), 0.8, 20);
    return protocol;
  }

  /// The largest |F_u - F_l| a record of a bed of @p n particles may show:
  /// pair forces cancel in the sum of the particles' out-of-balance forces,
  /// which leaves F_u - F_l (the die wall frictionless, radial), bounded by
  /// N times the largest particle residual, plus rounding.
  double
  punch_imbalance_bound(const DieRecord &r, const std::size_t n)
  {
    return static_cast<double>(n) * r.residual * r.mean_contact_force
           + 1e-12 * std::abs(r.upper_punch_force);
  }

  /// Eq. (16)'s rho_min from the last two states of an unloading branch:
  /// where the secant through their punch forces reaches zero. The solid
  /// volume over the punch gap is the density, so 1/rho is linear in the gap.
  double
  secant_separation_density(const DieRecord &before, const DieRecord &last)
  {
    const double F0 = before.upper_punch_force, F1 = last.upper_punch_force;
    const double h0 = 1 / before.relative_density,
                 h1 = 1 / last.relative_density;
    return 1 / (h0 + (h1 - h0) * F0 / (F0 - F1));
  }
} // namespace

/// A small deposited bed of Material 1 compacted, unloaded and ejected.
/// Checks conservation laws at every converged state: with a frictionless
/// die wall (radial forces only) the punch forces balance, |F_u - F_l|
/// bounded by the sum of the particles' residual forces (N max_i |F_i|); every
/// particle's net force is within the solver tolerance (recomputed
/// independently; an unjammed state of the bonded path within the relaxation
/// tolerance); unloading ends with a free upper punch and a lower density.
TEST(DieProtocol, PunchForcesBalanceAndBranchesAreConsistent)
{
  const Bed          bed      = deposit(150, 3);
  const ContactModel model    = material1();
  DieProtocol        protocol = compaction_to_080(bed);
  protocol.unloading_points   = {0.8};
  DieCompaction      die(bed, model, protocol);
  std::ostringstream csv;
  die.set_output(&csv, nullptr);
  ASSERT_NO_THROW(die.run());

  const double tol    = EquilibriumOptions{}.force_tolerance;
  bool         saw[3] = {false, false, false};
  for (const DieRecord &r : die.records())
    {
      saw[0] |= r.stage == "compaction";
      saw[1] |= r.stage == "unloading";
      saw[2] |= r.stage == "ejection";
      // Newton states to the solver tolerance; unjammed relaxations of the
      // bonded path to theirs, or every net force below the resolution.
      if (r.relaxed)
        EXPECT_TRUE(r.residual <= protocol.consolidation.relative_tolerance
                    || r.residual * r.mean_contact_force
                         <= die.force_resolution())
          << r.step;
      else
        EXPECT_LE(r.residual, tol) << r.stage << " step " << r.step;
      if (!(r.stage == "compaction" && r.step == 0)) // the deposit
        {
          EXPECT_LE(std::abs(r.upper_punch_force - r.lower_punch_force),
                    punch_imbalance_bound(r, bed.particles.size()))
            << r.stage << " step " << r.step;
        }
    }
  EXPECT_TRUE(saw[0] && saw[1] && saw[2]);

  // The unloading branch ends at its first state whose punch force is below
  // the force resolution, and rho_min is the secant's zero there.
  std::vector<DieRecord> unloading;
  for (const DieRecord &r : die.records())
    if (r.stage == "unloading")
      unloading.push_back(r);
  ASSERT_GE(unloading.size(), 2u);
  for (std::size_t i = 0; i + 1 < unloading.size(); ++i)
    EXPECT_GT(unloading[i].upper_punch_force, die.force_resolution()) << i;
  EXPECT_LE(unloading.back().upper_punch_force, die.force_resolution());

  // Independent residual of the final compaction state.
  Bed               final_bed = die.bed();
  ContactAssembler  a;
  Eigen::VectorXd   F;
  const ContactSums s = a.residual(final_bed, model, F);
  EXPECT_LE(max_particle_norm(F), tol * s.mean_force);
  EXPECT_GT(s.wall_force[int(Wall::upper_punch)], 0.0);

  ASSERT_EQ(die.branches().size(), 1u);
  const BranchSummary &b = die.branches()[0];
  EXPECT_NEAR(b.rho_max_in_die, 0.8, 1e-9);
  EXPECT_LT(b.rho_min_in_die, b.rho_max_in_die);
  EXPECT_GT(b.elastic_recovery_rho, 0.0);
  // Eq. (16): both recoveries agree to first order, eps_H = eps_rho /
  // (1 - eps_rho) exactly since rho H is constant.
  EXPECT_NEAR(b.elastic_recovery_H,
              b.elastic_recovery_rho / (1 - b.elastic_recovery_rho),
              1e-9);
  EXPECT_NEAR(b.rho_min_in_die,
              secant_separation_density(unloading.end()[-2], unloading.back()),
              1e-12);
  EXPECT_GE(b.residual_radial_pressure, 0.0);
  // Gonzalez 2018 Sec. 5: the tablet out of the die has about the density
  // at the end of unloading, rho_tablet ~ rho_min^in-die.
  EXPECT_NEAR(b.rho_tablet, b.rho_min_in_die, 0.03);
  EXPECT_NE(csv.str().find("stage,branch,step"), std::string::npos);
}

/// The progress stream belongs to the caller (std::cout in compax): the
/// protocol's progress lines change its precision and flags, and must
/// leave them as they were.
TEST(DieProtocol, ProgressLeavesTheCallersStreamFormat)
{
  const Bed          bed   = deposit(60, 5);
  const ContactModel model = material1();
  DieProtocol        protocol;
  protocol.compaction_targets = density_targets(bed.relative_density(), 0.7, 3);
  protocol.eject              = false;
  DieCompaction      die(bed, model, protocol);
  std::ostringstream progress;
  progress.precision(7);
  progress.setf(std::ios::scientific, std::ios::floatfield);
  const auto flags = progress.flags();
  die.set_output(nullptr, &progress);
  ASSERT_NO_THROW(die.run());
  EXPECT_FALSE(progress.str().empty());
  EXPECT_EQ(progress.precision(), 7);
  EXPECT_EQ(progress.flags(), flags);
}

namespace
{
  /// The loose-path study of these tests: @p bed compacted to 0.7 in 15
  /// steps, without ejection, through the given unjammed equilibrium.
  DieProtocol
  loose_path_protocol(const Bed &bed, const UnjammedEquilibrium unjammed)
  {
    DieProtocol protocol;
    protocol.compaction_targets
      = density_targets(bed.relative_density(), 0.7, 15);
    protocol.eject                = false;
    protocol.unjammed_equilibrium = unjammed;
    return protocol;
  }

  /**
   * Compacts a small bed of Material 1 along the bonded path with the given
   * unjammed equilibrium and checks that every state, loose ones included,
   * is balanced to the solver tolerance (each residual recomputed
   * independently at the end of its step; the relative tolerance, or every
   * net force below the floor of 1e-6 of a particle's share of 0.5 MPa),
   * and that the bed jams at the first state whose punches carry 0.5 MPa.
   * @return the records' relaxed flags of the loose states.
   */
  std::vector<int>
  expect_loose_states_balanced(const UnjammedEquilibrium unjammed)
  {
    const Bed          bed   = deposit(150, 3);
    const ContactModel model = material1();
    DieCompaction      die(bed, model, loose_path_protocol(bed, unjammed));
    EXPECT_NO_THROW(die.run());
    const double jamming = 0.5e6;
    const double tol     = EquilibriumOptions{}.force_tolerance;
    const double floor
      = tol * jamming * pi * std::pow(bed.particles.mean_radius(), 2);
    double           first_jammed = 0.0;
    std::vector<int> relaxed;
    for (const DieRecord &r : die.records())
      {
        if (r.step == 0)
          continue; // the deposit, recorded as filled
        EXPECT_TRUE(r.residual <= tol
                    || r.residual * r.mean_contact_force <= floor)
          << r.step << " residual " << r.residual;
        const bool loose
          = std::max(r.upper_punch_pressure, r.lower_punch_pressure) < jamming;
        if (!loose && first_jammed == 0.0)
          first_jammed = r.relative_density;
        if (loose && first_jammed == 0.0)
          relaxed.push_back(r.relaxed);
      }
    EXPECT_GT(relaxed.size(), 2u); // the path had loose states to balance
    EXPECT_GT(first_jammed, 0.0);  // and jammed
    EXPECT_EQ(die.jamming_density(), first_jammed);
    return relaxed;
  }
} // namespace

/// With Newton after each unjammed relaxation, the loose states of the
/// bonded path are balanced to the solver tolerance by Newton (none is a
/// relaxed state).
TEST(DieProtocol, NewtonAfterRelaxationBalancesLooseStatesToTheSolverTolerance)
{
  for (const int relaxed : expect_loose_states_balanced(
         UnjammedEquilibrium::relaxation_then_newton))
    EXPECT_EQ(relaxed, 0);
}

/// A balanced relaxation brings the loose states to the solver tolerance
/// itself: they are relaxed states, balanced like Newton's.
TEST(DieProtocol, BalancedRelaxationBalancesLooseStatesToTheSolverTolerance)
{
  for (const int relaxed :
       expect_loose_states_balanced(UnjammedEquilibrium::balanced_relaxation))
    EXPECT_EQ(relaxed, 1);
}

/// The same with L-BFGS as the minimiser of the balanced relaxation.
TEST(DieProtocol, BalancedLbfgsBalancesLooseStatesToTheSolverTolerance)
{
  for (const int relaxed :
       expect_loose_states_balanced(UnjammedEquilibrium::balanced_lbfgs))
    EXPECT_EQ(relaxed, 1);
}

/// Algorithm 1 as printed (UnjammedEquilibrium::least_squares): the loose
/// steps stop where the Gauss-Newton step on |F|^2 vanishes, balanced or
/// not, yet the path reaches the first state whose punches carry 0.5 MPa,
/// and from there on every state is Newton's, balanced to the solver
/// tolerance. At every state the punch forces differ by no more than the
/// particles' summed residual (frictionless die wall: radial forces only).
TEST(DieProtocol, LeastSquaresPathBalancesEveryJammedState)
{
  const Bed          bed   = deposit(150, 3);
  const ContactModel model = material1();
  DieCompaction      die(
    bed, model, loose_path_protocol(bed, UnjammedEquilibrium::least_squares));
  ASSERT_NO_THROW(die.run());
  const double jamming      = 0.5e6;
  const double tol          = EquilibriumOptions{}.force_tolerance;
  double       first_jammed = 0.0;
  int          jammed = 0, loose = 0;
  for (const DieRecord &r : die.records())
    {
      if (r.step == 0)
        continue;
      // Every state, loose or not: the pair forces cancel in the sum of
      // the particles' residuals, which leaves F_u - F_l.
      EXPECT_LE(std::abs(r.upper_punch_force - r.lower_punch_force),
                punch_imbalance_bound(r, bed.particles.size()))
        << r.step;
      const bool below
        = std::max(r.upper_punch_pressure, r.lower_punch_pressure) < jamming;
      if (below && first_jammed == 0.0)
        {
          ++loose;
          continue;
        }
      if (first_jammed == 0.0)
        first_jammed = r.relative_density;
      ++jammed;
      EXPECT_LE(r.residual, tol) << r.step;
    }
  EXPECT_GT(loose, 2);
  EXPECT_GT(jammed, 2);
  EXPECT_EQ(die.jamming_density(), first_jammed);
}

/// Solver/Stall relaxation = lbfgs: where the trust-region Newton stalls on
/// a jammed step, L-BFGS relaxes the bed instead of FIRE, and Newton then
/// balances every jammed state to the solver tolerance as before (each
/// record's residual; the punch forces cancel up to N times the largest
/// net force, the die wall being frictionless). The two minimisers take
/// different routes through the stalls (the loose steps, relaxed by L-BFGS
/// in both runs, are the same), so the option is in force.
TEST(DieProtocol, LbfgsStallRelaxationBalancesEveryJammedState)
{
  const Bed          bed      = deposit(150, 3);
  const ContactModel model    = material1();
  DieProtocol        protocol = compaction_to_080(bed);
  protocol.eject              = false;
  const double tol            = EquilibriumOptions{}.force_tolerance;

  std::vector<long> relaxation_work;
  for (const auto stall : {EquilibriumOptions::StallRelaxation::fire,
                           EquilibriumOptions::StallRelaxation::lbfgs})
    {
      EquilibriumOptions equilibrium;
      equilibrium.stall_relaxation = stall;
      DieCompaction die(bed, model, protocol, equilibrium);
      ASSERT_NO_THROW(die.run());
      int jammed = 0;
      for (const DieRecord &r : die.records())
        {
          if (r.step == 0 || r.relaxed)
            continue; // the deposit; loose states (their own tests)
          ++jammed;
          EXPECT_LE(r.residual, tol) << r.step;
          EXPECT_LE(std::abs(r.upper_punch_force - r.lower_punch_force),
                    punch_imbalance_bound(r, bed.particles.size()))
            << r.step;
        }
      EXPECT_GT(jammed, 5);
      relaxation_work.push_back(die.work.fire_iterations);
    }
  EXPECT_NE(relaxation_work[0], relaxation_work[1]);
}

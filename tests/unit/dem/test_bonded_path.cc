// The quasi-static path with the bonding physics on (issue #15): bridges
// formed on converged states hold a cluster together and carry tension,
// and Eq. (13) changes histories on converged states only.
#include "dem/solver/load_stepper.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace compax::dem;

namespace
{
  using compax::testing::material1::R;

  /// Material 1 of Gonzalez 2018, with or without bridges to the walls.
  ContactModel
  material1(bool wall_bonding)
  {
    ContactModel model = compax::testing::material1::contact_model();
    model.wall_bonding = wall_bonding;
    return model;
  }

  /// The most tensile force of a law's elastic branch for a history, by a
  /// dense scan of the overlap between breakage and the plastic overlap
  /// refined by golden sections: the pull-off force of that contact [N].
  double
  pull_off(const BondedElastoplasticLaw &law, const ContactHistory &h)
  {
    const double lo0 = law.breakage_overlap(BondedElastoplasticLaw::a_p(h));
    const double hi0 = law.plastic_overlap(BondedElastoplasticLaw::a_p(h));
    auto         P   = [&](double g) {
      return law
        .response(g,
                  BondedElastoplasticLaw::a_p(h),
                  BondedElastoplasticLaw::a_B(h))
        .force;
    };
    int       best = 0;
    const int n    = 4000;
    for (int k = 1; k <= n; ++k)
      if (P(lo0 + (hi0 - lo0) * k / n) < P(lo0 + (hi0 - lo0) * best / n))
        best = k;
    double       a = lo0 + (hi0 - lo0) * std::max(0, best - 1) / n;
    double       b = lo0 + (hi0 - lo0) * std::min(n, best + 1) / n;
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int it = 0; it < 200; ++it)
      {
        const double c = b - r * (b - a), d = a + r * (b - a);
        (P(c) < P(d) ? b : a) = P(c) < P(d) ? d : c;
      }
    return P(0.5 * (a + b));
  }

  /// Wall forces of the bed's current state.
  ContactSums
  sums_of(Bed &bed, const ContactModel &model)
  {
    ContactAssembler a;
    Eigen::VectorXd  F;
    return a.residual(bed, model, F);
  }
} // namespace

/// A chain of three spheres between the punches, bonded to each other and
/// to the punches, is compacted past plastic onset and unloaded: at zero
/// punch force it stays together by its bridges, and drawn further apart
/// its largest tension equals the pull-off force of its weakest contact,
/// computed from the contact law at the committed histories.
TEST(BondedPath, ChainStaysTogetherAndPullsOffAtTheLawsForce)
{
  const ContactModel model = material1(true);
  Bed                bed;
  bed.walls.die_present = false;
  bed.walls.diameter    = 20 * R;
  bed.walls.upper_punch = 6 * R;
  bed.contacts.set_skin(0.3 * R);
  for (int k = 0; k < 3; ++k)
    bed.particles.add({0.0, 0.0, (2 * k + 1) * R}, R);
  LoadStepper stepper(model);

  // Compaction by 4 % of the chain's height in ten steps.
  DieWalls w = bed.walls;
  for (int step = 0; step < 10; ++step)
    {
      w.upper_punch -= 0.024 * R;
      ASSERT_TRUE(stepper.advance(bed, w).converged);
    }
  for (const auto &c : bed.contacts.pairs)
    EXPECT_GT(BondedElastoplasticLaw::a_B(c.history), 0.0);
  for (const auto &c : bed.contacts.walls)
    EXPECT_GT(BondedElastoplasticLaw::a_B(c.history), 0.0);
  ASSERT_EQ(bed.contacts.pairs.size(), 2u);
  ASSERT_EQ(bed.contacts.walls.size(), 2u);

  // The weakest contact's pull-off, from the law at the committed state.
  double weakest = -1e300;
  for (const auto &c : bed.contacts.pairs)
    weakest = std::max(weakest, pull_off(bonded_law(c.law), c.history));
  for (const auto &c : bed.contacts.walls)
    weakest = std::max(weakest, pull_off(bonded_law(c.law), c.history));
  ASSERT_LT(weakest, 0.0);

  // Unloading: the punch withdraws in small steps; the chain follows in
  // tension until a bridge breaks.
  double most_tensile = 0.0;
  bool   passed_zero  = false;
  for (int step = 0; step < 4000; ++step)
    {
      w.upper_punch += 2e-5 * R;
      const LoadStepResult r = stepper.advance(bed, w);
      if (!r.converged)
        break;
      const double F = r.last.sums.wall_force[int(Wall::upper_punch)];
      if (F < 0.0 && !passed_zero)
        {
          // The punch force changed sign: the chain holds by its bridges,
          // every contact still bonded with a positive contact radius.
          passed_zero = true;
          for (const auto &c : bed.contacts.pairs)
            {
              const double gamma = 2 * R
                                   - (bed.particles.positions[c.j]
                                      - bed.particles.positions[c.i])
                                       .norm();
              EXPECT_GT(BondedElastoplasticLaw::a_B(c.history), 0.0);
              EXPECT_GT(bonded_law(c.law)
                          .response(gamma,
                                    BondedElastoplasticLaw::a_p(c.history),
                                    BondedElastoplasticLaw::a_B(c.history))
                          .contact_radius,
                        0.0);
            }
        }
      most_tensile = std::min(most_tensile, F);
      bool broken  = false;
      for (const auto &c : bed.contacts.pairs)
        broken = broken || BondedElastoplasticLaw::a_B(c.history) == 0.0;
      for (const auto &c : bed.contacts.walls)
        broken = broken || BondedElastoplasticLaw::a_B(c.history) == 0.0;
      if (broken)
        break;
    }
  ASSERT_TRUE(passed_zero);
  EXPECT_NEAR(most_tensile, weakest, 2e-3 * std::abs(weakest));
}

/// A triangle of three spheres standing on the lower punch, its apex under
/// the upper punch, is squeezed by the die wall and the punch so that its
/// base forms a bridge; the die wall is then removed. The bonded triangle
/// is hypostatic (frictionless punches, nothing holds its base spheres
/// apart but the bridge) and still carries the punch load in equilibrium,
/// its bridge in tension. The same triangle with frozen (virgin)
/// histories cannot: its base slides apart and the punch comes free.
TEST(BondedPath, HypostaticTriangleStandsOnlyByItsBridge)
{
  const ContactModel model    = material1(false);
  auto               squeezed = [&]() {
    Bed bed;
    bed.walls.diameter    = 4 * R;
    bed.walls.upper_punch = 2 * R + std::sqrt(3.0) * R;
    bed.contacts.set_skin(0.3 * R);
    bed.particles.add({-R, 0.0, R}, R);
    bed.particles.add({R, 0.0, R}, R);
    bed.particles.add({0.0, 0.0, R + std::sqrt(3.0) * R}, R);
    LoadStepper stepper(model);
    DieWalls    w = bed.walls;
    for (int step = 0; step < 5; ++step)
      {
        w.diameter -= 0.004 * R;
        w.upper_punch -= 0.004 * R;
        EXPECT_TRUE(stepper.advance(bed, w).converged);
      }
    return bed;
  };

  // Bonded: the base bridge formed by Eq. (13) on the converged steps.
  Bed                bonded = squeezed();
  const PairContact *base   = nullptr;
  for (const auto &c : bonded.contacts.pairs)
    if (c.i + c.j == 1)
      base = &c;
  ASSERT_NE(base, nullptr);
  ASSERT_GT(BondedElastoplasticLaw::a_B(base->history), 0.0);
  const double load = sums_of(bonded, model).wall_force[int(Wall::upper_punch)];
  ASSERT_GT(load, 0.0);

  // Frozen: the same squeezed state with virgin histories.
  Bed frozen = bonded;
  for (auto &c : frozen.contacts.pairs)
    c.history = ContactHistory{};
  for (auto &c : frozen.contacts.walls)
    c.history = ContactHistory{};

  // The die wall opens in small steps until it carries nothing, then goes
  // (the ejection of the die protocol), at a fixed upper punch.
  EquilibriumOptions options;
  options.force_floor = 1e-12;
  for (Bed *bed : {&bonded, &frozen})
    {
      LoadStepper stepper(model, options);
      DieWalls    w = bed->walls;
      for (int step = 0; step < 200; ++step)
        {
          w.diameter += 2e-4 * R;
          ASSERT_TRUE(stepper.advance(*bed, w).converged);
          if (bed == &frozen) // frozen: nothing is committed
            for (auto &c : bed->contacts.pairs)
              c.history = ContactHistory{};
          if (sums_of(*bed, model).wall_force[int(Wall::die)] == 0.0)
            break;
        }
      w.die_present = false;
      ASSERT_TRUE(stepper.advance(*bed, w).converged);
    }
  const ContactSums b = sums_of(bonded, model);
  const ContactSums f = sums_of(frozen, model);
  // The bonded triangle still carries most of the punch load, balanced by
  // the lower punch, with its base bridge pulling.
  EXPECT_GT(b.wall_force[int(Wall::upper_punch)], 0.5 * load);
  EXPECT_NEAR(b.wall_force[int(Wall::upper_punch)],
              b.wall_force[int(Wall::lower_punch)],
              1e-6 * load);
  for (const auto &c : bonded.contacts.pairs)
    {
      if (c.i + c.j != 1)
        continue;
      EXPECT_LT(bonded_law(c.law)
                  .response(2 * R
                              - (bonded.particles.positions[1]
                                 - bonded.particles.positions[0])
                                  .norm(),
                            BondedElastoplasticLaw::a_p(c.history),
                            BondedElastoplasticLaw::a_B(c.history))
                  .force,
                0.0);
    }
  // The frozen one carries nothing.
  EXPECT_LE(std::abs(f.wall_force[int(Wall::upper_punch)]), 1e-9 * load);
}

/// Eq. (13) applies on converged states only: a load step that fails
/// after all its cut-backs leaves every position and every a_p, a_B as they
/// were; a converged one changes them.
TEST(BondedPath, FailedStepLeavesHistoriesUntouched)
{
  const ContactModel model = material1(true);
  Bed                bed;
  // Unequal spheres: the affine predictor is no equilibrium (for equal
  // ones on the plastic branch it would be, exactly).
  bed.walls.diameter    = 6 * R;
  bed.walls.upper_punch = 3.6 * R;
  bed.contacts.set_skin(0.3 * R);
  bed.particles.add({0.0, 0.0, R}, R);
  bed.particles.add({0.0, 0.0, 2.8 * R}, 0.8 * R);
  LoadStepper stepper(model);
  DieWalls    w = bed.walls;
  w.upper_punch -= 0.02 * R;
  ASSERT_TRUE(stepper.advance(bed, w).converged);
  auto histories = [](const Bed &b) {
    std::vector<double> h;
    for (const auto &c : b.contacts.pairs)
      h.insert(h.end(),
               {BondedElastoplasticLaw::a_p(c.history),
                BondedElastoplasticLaw::a_B(c.history)});
    for (const auto &c : b.contacts.walls)
      h.insert(h.end(),
               {BondedElastoplasticLaw::a_p(c.history),
                BondedElastoplasticLaw::a_B(c.history)});
    return h;
  };
  const std::vector<double> before = histories(bed);
  const auto                x      = bed.particles.positions;
  ASSERT_GT(*std::max_element(before.begin(), before.end()), 0.0);

  // No Newton iteration, no cut-back, no FIRE: the step cannot converge.
  EquilibriumOptions hopeless;
  hopeless.max_iterations  = 0;
  hopeless.fire_iterations = 0;
  LoadSteppingOptions no_cutback;
  no_cutback.min_fraction = 1.0;
  LoadStepper failing(model, hopeless, no_cutback);
  DieWalls    further = bed.walls;
  further.upper_punch -= 0.05 * R;
  const LoadStepResult r = failing.advance(bed, further);
  ASSERT_FALSE(r.converged);
  EXPECT_EQ(histories(bed), before);
  EXPECT_EQ(bed.particles.positions, x);

  // The same step with the default solver converges and grows a_p.
  ASSERT_TRUE(stepper.advance(bed, further).converged);
  EXPECT_NE(histories(bed), before);
}

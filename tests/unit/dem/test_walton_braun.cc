// The Walton-Braun/Luding hysteretic spring against values worked out by
// hand from its definition (Luding 2008), its stiffness against central
// differences of its force, and a loading path through updated_history.
//
// Hand values: k1 = 1e4 N/m, k2_max = 5 k1, kc = k1/2, phi_F = 0.1 and an
// effective radius R = 1e-4 m (two spheres of 2e-4 m), so the plastic flow
// limit is delta* = 5/4 * 0.1 * 2e-4 = 2.5e-5 m. Loaded to delta_max =
// 1e-5 m: F = 0.1 N; k2 = 1e4 + 4e4 * 1e-5 / 2.5e-5 = 2.6e4 N/m;
// k2 delta_0 = (k2 - k1) delta_max = 0.16 N, so at delta = 8e-6 m the
// un/reloading force is 2.6e4 * 8e-6 - 0.16 = 0.048 N; delta_min =
// 1.6e4 / 3.1e4 * 1e-5 m, and at 3e-6 m the adhesive force is -5e3 * 3e-6
// = -0.015 N.

#include "dem/contact/contact_law_registry.h"
#include "dem/contact/walton_braun.h"

#include "dem/contact/pair_properties.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace
{
  using namespace compax::dem;

  WaltonBraunLaw::Parameters
  hand_parameters()
  {
    WaltonBraunLaw::Parameters p;
    p.loading_stiffness         = 1e4;
    p.unloading_stiffness_ratio = 5.0;
    p.adhesion_stiffness_ratio  = 0.5;
    p.plasticity_depth          = 0.1;
    return p;
  }

  const WaltonBraunLaw law
    = WaltonBraunLaw::for_pair(2e-4, 2e-4, hand_parameters());
} // namespace

TEST(WaltonBraun, BranchesEqualTheHandComputedValues)
{
  EXPECT_NEAR(law.effective_radius(), 1e-4, 1e-18);
  EXPECT_NEAR(law.plastic_flow_limit(), 2.5e-5, 1e-18);
  const double delta_max = 1e-5;
  EXPECT_NEAR(law.unloading_stiffness(delta_max), 2.6e4, 1e-9);
  EXPECT_NEAR(law.plastic_overlap(delta_max), 0.16 / 2.6e4, 1e-18);
  EXPECT_NEAR(law.minimum_overlap(delta_max), 1.6e4 / 3.1e4 * 1e-5, 1e-18);

  // Loading (at and beyond delta_max), un/reloading, adhesion, no contact.
  ContactResponse r = law.response(1e-5, delta_max);
  EXPECT_NEAR(r.force, 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(r.stiffness, 1e4);
  r = law.response(1.2e-5, delta_max);
  EXPECT_NEAR(r.force, 0.12, 1e-15);
  r = law.response(8e-6, delta_max);
  EXPECT_NEAR(r.force, 0.048, 1e-15);
  EXPECT_DOUBLE_EQ(r.stiffness, 2.6e4);
  EXPECT_NEAR(r.contact_radius, std::sqrt(1e-4 * 8e-6), 1e-18);
  r = law.response(3e-6, delta_max);
  EXPECT_NEAR(r.force, -0.015, 1e-15);
  EXPECT_DOUBLE_EQ(r.stiffness, -5e3);
  r = law.response(-1e-6, delta_max);
  EXPECT_EQ(r.force, 0.0);
  EXPECT_EQ(r.stiffness, 0.0);

  // Past the plastic flow limit k2 stays at k2_max: delta_0 = 0.8 delta_max.
  EXPECT_DOUBLE_EQ(law.unloading_stiffness(5e-5), 5e4);
  EXPECT_NEAR(law.plastic_overlap(5e-5), 4e-5, 1e-18);

  // Without adhesion the contact carries nothing below delta_0.
  WaltonBraunLaw::Parameters p = hand_parameters();
  p.adhesion_stiffness_ratio   = 0.0;
  const auto plain             = WaltonBraunLaw::for_pair(2e-4, 2e-4, p);
  EXPECT_DOUBLE_EQ(plain.minimum_overlap(delta_max),
                   plain.plastic_overlap(delta_max));
  EXPECT_EQ(plain.response(3e-6, delta_max).force, 0.0);
  EXPECT_NEAR(plain.response(8e-6, delta_max).force, 0.048, 1e-15);
}

TEST(WaltonBraun, ForceIsContinuousAcrossTheBranches)
{
  // Across each kink the force changes by at most the steepest slope,
  // k2_max = 5e4 N/m, times the width of the window: no jump.
  const double delta_max = 1e-5, window = 1e-12;
  for (const double at : {delta_max,
                          law.minimum_overlap(delta_max),
                          law.plastic_overlap(delta_max)})
    EXPECT_LE(std::abs(law.response(at * (1 + window), delta_max).force
                       - law.response(at * (1 - window), delta_max).force),
              5e4 * 2 * window * at * (1 + 1e-3))
      << "at delta = " << at;
}

TEST(WaltonBraun, StiffnessEqualsCentralDifferenceOfTheForce)
{
  const double delta_max = 1e-5;
  const double h         = 1e-12;
  // Inside each branch, away from the kinks by far more than h.
  for (const double delta : {2e-6, 4e-6, 7e-6, 9e-6, 1.5e-5, 4e-5})
    {
      const double fd = (law.response(delta + h, delta_max).force
                         - law.response(delta - h, delta_max).force)
                        / (2 * h);
      const double k = law.response(delta, delta_max).stiffness;
      EXPECT_NEAR(k, fd, 1e-6 * std::abs(k)) << "delta = " << delta;
    }
}

TEST(WaltonBraun, ConvergedStatesRaiseTheLargestOverlapOnly)
{
  // Load to 1e-5 in converged steps, unload to 3e-6, reload to 1e-5: the
  // history follows the loading branch up, the un/reloading branch down
  // and up again, and a trial state never changes it.
  ContactHistory h;
  for (int k = 1; k <= 10; ++k)
    {
      const double delta = 1e-6 * k;
      EXPECT_NEAR(law.evaluate(delta, h).force, 1e4 * delta, 1e-15);
      h = law.updated_history(delta, h);
    }
  EXPECT_DOUBLE_EQ(WaltonBraunLaw::delta_max(h), 1e-5);
  EXPECT_EQ(h[1], 0.0); // the slot the law does not declare
  for (const double delta : {8e-6, 3e-6, 8e-6})
    {
      h = law.updated_history(delta, h);
      EXPECT_DOUBLE_EQ(WaltonBraunLaw::delta_max(h), 1e-5);
    }
  EXPECT_NEAR(law.evaluate(8e-6, h).force, 0.048, 1e-15);
  EXPECT_NEAR(law.evaluate(1e-5, h).force, 0.1, 1e-15);
}

/// The stiffness the particle solvers take for elastic unloading (the
/// moduli of a compact) and the plastic-loading test of Eq. 13's force
/// resolution, against the hand values: loaded to 1e-5 m (delta_max below
/// it) the contact unloads along k2 = 2.6e4 N/m; already on the
/// un/reloading branch it keeps k2, on the adhesive branch -kc = -5e3 N/m.
TEST(WaltonBraun, UnloadsAlongTheBranchItWouldFollow)
{
  ContactHistory loading;
  loading[WaltonBraunLaw::delta_max_slot] = 5e-6;
  EXPECT_NEAR(law.unloading_stiffness(1e-5, loading, {}), 2.6e4, 1e-9);
  EXPECT_TRUE(law.loads_plastically(1e-5, loading, {}));
  ContactHistory unloaded;
  unloaded[WaltonBraunLaw::delta_max_slot] = 1e-5;
  EXPECT_NEAR(law.unloading_stiffness(8e-6, unloaded, {}), 2.6e4, 1e-9);
  EXPECT_NEAR(law.unloading_stiffness(3e-6, unloaded, {}), -5e3, 1e-9);
  EXPECT_FALSE(law.loads_plastically(8e-6, unloaded, {}));
  EXPECT_FALSE(law.loads_plastically(1e-5, unloaded, {}));
}

TEST(WaltonBraun, RejectsParametersOutsideTheirRange)
{
  WaltonBraunLaw::Parameters p = hand_parameters();
  p.loading_stiffness          = 0.0;
  EXPECT_THROW(WaltonBraunLaw(1e-4, p), std::invalid_argument);
  p                           = hand_parameters();
  p.unloading_stiffness_ratio = 0.5;
  EXPECT_THROW(WaltonBraunLaw(1e-4, p), std::invalid_argument);
  p                          = hand_parameters();
  p.adhesion_stiffness_ratio = -1.0;
  EXPECT_THROW(WaltonBraunLaw(1e-4, p), std::invalid_argument);
}

TEST(ContactLawRegistry, EveryLawBuildsFromItsOwnDefaultsUnderItsName)
{
  ASSERT_FALSE(registered_contact_laws().empty());
  for (const RegisteredContactLaw &entry : registered_contact_laws())
    {
      LawParameterValues defaults;
      for (const LawParameter &p : entry.parameters)
        {
          EXPECT_TRUE(defaults.emplace(p.name, p.default_value).second)
            << entry.name << ": " << p.name << " declared twice";
          EXPECT_FALSE(p.unit.empty()) << entry.name << ": " << p.name;
        }
      const ContactBodies wall{1e-4, 5e9, 0.25, rigid, rigid, 0.0};
      const auto          law = entry.make(defaults, wall);
      ASSERT_TRUE(law);
      EXPECT_EQ(law->name(), entry.name);
      EXPECT_EQ(find_contact_law(entry.name), &entry);
      // A context, where a law declares one, is a function of the overlap.
      if (entry.context)
        {
          EXPECT_TRUE(std::isfinite(
            entry.context(defaults, wall)(1e-7).nonlocal_overlap));
        }
    }
  EXPECT_EQ(find_contact_law("no-such-law"), nullptr);

  // The Walton-Braun entry builds the law of its values: k1 sets the
  // loading branch against a wall (R = R1).
  const RegisteredContactLaw *entry = find_contact_law("walton-braun");
  ASSERT_NE(entry, nullptr);
  LawParameterValues values{{"Loading stiffness", 1e4},
                            {"Unloading stiffness ratio", 5.0},
                            {"Adhesion stiffness ratio", 0.5},
                            {"Plasticity depth", 0.1}};
  const auto         law
    = entry->make(values, ContactBodies{1e-4, 5e9, 0.25, rigid, rigid, 0.0});
  EXPECT_NEAR(law->evaluate(1e-6, ContactHistory{}).force, 1e-2, 1e-16);
  EXPECT_NEAR(dynamic_cast<const WaltonBraunLaw &>(*law).plastic_flow_limit(),
              5.0 / 4.0 * 0.1 * 2e-4,
              1e-18);
}

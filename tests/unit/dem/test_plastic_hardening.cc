// The plastic-hardening law (Gonzalez 2018, plastic loading of Eqs. 1-2 at
// every overlap) against the printed formulas evaluated here by hand, its
// stiffness against central differences, and its reversibility against the
// bonded law with K_Ic = 0, which unloads elastically from the same branch.
//
// Hand values: two spheres of R = 2e-4 m (effective radius 1e-4 m) with
// kappa = 150 MPa and m = 2, so k = 3 / sqrt(6), c^2 = 1.43 exp(-0.485),
// n_p = pi k R^{-1/2} (2 / kappa^2)^{-1/2} = pi k R^{-1/2} kappa / sqrt(2),
// a^2 = 2 c^2 R gamma and P = n_p a^{5/2}. Against a rigid flat the wall's
// kappa drops out: n_p = pi k R1^{-1/2} kappa with R = R1.

#include "dem/contact/bonded_elastoplastic.h"
#include "dem/contact/contact_law_registry.h"
#include "dem/contact/pair_properties.h"
#include "dem/contact/plastic_hardening.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace
{
  using namespace compax::dem;

  constexpr double                      kappa = 150e6;
  const PlasticHardeningLaw::Parameters parameters{kappa, 2.0};

  /// P = n_p (2 c^2 R gamma)^{5/4} of Eqs. 1-2 for m = 2.
  double
  hand_force(const double gamma, const double R, const double n_p)
  {
    const double c2 = 1.43 * std::exp(-0.97 / 2.0);
    return n_p * std::pow(2.0 * c2 * R * gamma, 1.25);
  }

  const double k_m = 3.0 / std::sqrt(6.0);
} // namespace

TEST(PlasticHardening, ForceIsThePrintedPlasticLoadingBranch)
{
  const auto   pair   = PlasticHardeningLaw::for_pair(2e-4, 2e-4, parameters);
  const double R      = 1e-4;
  const double n_pair = M_PI * k_m / std::sqrt(R) * kappa / std::sqrt(2.0);
  EXPECT_NEAR(pair.plastic_coefficient(), n_pair, 1e-12 * n_pair);
  for (const double gamma : {1e-8, 3e-7, 2e-6, 1e-5})
    {
      const ContactResponse r = pair.evaluate(gamma, ContactHistory{});
      EXPECT_NEAR(r.force, hand_force(gamma, R, n_pair), 1e-12 * r.force)
        << "gamma = " << gamma;
      const double c2 = 1.43 * std::exp(-0.97 / 2.0);
      EXPECT_NEAR(r.contact_radius, std::sqrt(2.0 * c2 * R * gamma), 1e-18);
    }
  EXPECT_EQ(pair.evaluate(0.0, ContactHistory{}).force, 0.0);
  EXPECT_EQ(pair.evaluate(-1e-6, ContactHistory{}).stiffness, 0.0);

  const auto   wall   = PlasticHardeningLaw::for_pair(2e-4, rigid, parameters);
  const double n_wall = M_PI * k_m / std::sqrt(2e-4) * kappa;
  EXPECT_NEAR(wall.plastic_coefficient(), n_wall, 1e-12 * n_wall);
  EXPECT_NEAR(wall.evaluate(2e-6, ContactHistory{}).force,
              hand_force(2e-6, 2e-4, n_wall),
              1e-12 * hand_force(2e-6, 2e-4, n_wall));
}

TEST(PlasticHardening, StiffnessEqualsCentralDifferenceOfTheForce)
{
  const auto law = PlasticHardeningLaw::for_pair(2e-4, 3e-4, parameters);
  for (const double gamma : {1e-7, 1e-6, 5e-6, 2e-5})
    {
      const double h  = 1e-4 * gamma;
      const double fd = (law.evaluate(gamma + h, ContactHistory{}).force
                         - law.evaluate(gamma - h, ContactHistory{}).force)
                        / (2 * h);
      const double k = law.evaluate(gamma, ContactHistory{}).stiffness;
      EXPECT_NEAR(k, fd, 1e-7 * k) << "gamma = " << gamma;
    }
}

/// No elastic unloading: after converged states loaded to 1e-5 m, the law
/// unloads along its loading branch (history unchanged, the unloading
/// stiffness that of the branch), where the bonded law with K_Ic = 0 from
/// the same loading unloads along its stiffer elastic branch and carries
/// less at every smaller overlap.
TEST(PlasticHardening, UnloadingRetracesLoadingUnlikeTheBondedLaw)
{
  ElastoplasticMaterial material;
  material.youngs_modulus    = 5e9;
  material.poisson_ratio     = 0.25;
  material.plastic_stiffness = kappa;
  material.plastic_exponent  = 2.0;
  const auto bonded          = BondedElastoplasticLaw::for_pair(
    material, 2e-4, material, 2e-4, 0.0, 0.01);
  const auto plastic = PlasticHardeningLaw::for_pair(2e-4, 2e-4, parameters);

  ContactHistory h_bonded, h_plastic;
  for (int k = 1; k <= 10; ++k)
    {
      const double gamma = 1e-6 * k;
      // One branch while loading.
      EXPECT_NEAR(plastic.evaluate(gamma, h_plastic).force,
                  bonded.evaluate(gamma, h_bonded).force,
                  1e-12 * bonded.evaluate(gamma, h_bonded).force);
      h_bonded  = bonded.updated_history(gamma, h_bonded);
      h_plastic = plastic.updated_history(gamma, h_plastic);
    }
  EXPECT_EQ(h_plastic, ContactHistory{});
  EXPECT_FALSE(plastic.loads_plastically(2e-5, h_plastic, {}));
  for (const double gamma : {9e-6, 7e-6, 4e-6})
    {
      const double fresh = PlasticHardeningLaw::for_pair(2e-4, 2e-4, parameters)
                             .evaluate(gamma, ContactHistory{})
                             .force;
      EXPECT_EQ(plastic.evaluate(gamma, h_plastic).force, fresh);
      EXPECT_EQ(plastic.unloading_stiffness(gamma, h_plastic, {}),
                plastic.evaluate(gamma, h_plastic).stiffness);
      EXPECT_LT(bonded.evaluate(gamma, h_bonded).force, 0.9 * fresh)
        << "gamma = " << gamma;
    }
}

TEST(PlasticHardening, RegistryBuildsTheLawOfItsValues)
{
  const RegisteredContactLaw *entry = find_contact_law("plastic-hardening");
  ASSERT_NE(entry, nullptr);
  const LawParameterValues values{{"Plastic stiffness", 900e6},
                                  {"Plastic exponent", 2.0}};
  const auto   law = entry->make(values, {2e-4, 30e9, 0.25, rigid, rigid, 0.0});
  const double n_wall = M_PI * k_m / std::sqrt(2e-4) * 900e6;
  EXPECT_NEAR(law->evaluate(1e-6, ContactHistory{}).force,
              hand_force(1e-6, 2e-4, n_wall),
              1e-12 * hand_force(1e-6, 2e-4, n_wall));
  EXPECT_TRUE(law->history_variables().empty());
  EXPECT_FALSE(law->bonded(ContactHistory{}));
}

TEST(PlasticHardening, RejectsParametersOutsideTheirRange)
{
  EXPECT_THROW(PlasticHardeningLaw::for_pair(2e-4, 2e-4, {0.0, 2.0}),
               std::invalid_argument);
  EXPECT_THROW(PlasticHardeningLaw::for_pair(2e-4, 2e-4, {kappa, 0.5}),
               std::invalid_argument);
}

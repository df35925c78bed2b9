// Bonded elasto-plastic law of Gonzalez 2018 (Eqs. 3-5, 13): exact stiffness
// against finite differences, continuity and jump at the onset of unloading,
// closed forms of breakage and of the critical (pull-off) radius, the energy
// ratio chi of the Du et al. case, and the history update.

#include "dem/contact/bonded_elastoplastic.h"
#include "dem/contact/pair_properties.h"
#include "dem/contact/particle_law.h"
#include "dem/solver/history_update.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace compax::dem;

namespace
{
  const double pi = std::acos(-1.0);

  /// The Du et al. (2008) sphere of Gonzalez 2018 Sec. 3.3.
  ElastoplasticMaterial
  du_material()
  {
    return {233e9, 0.3, 12.1e9, 1.79};
  }
  constexpr double du_radius    = 1.3e-6;
  constexpr double du_toughness = 0.48e6;
  constexpr double du_gamma_max = 28.2e-9;

  BondedElastoplasticLaw
  du_on_flat(const double xi_B = 0.01, const bool regularized = true)
  {
    return BondedElastoplasticLaw::for_pair(du_material(),
                                            du_radius,
                                            ElastoplasticMaterial::rigid_wall(
                                              1.79),
                                            rigid,
                                            du_toughness,
                                            xi_B,
                                            regularized);
  }

  /// Paper quantities computed here from Sec. 2, independently of the law.
  struct Hand
  {
    double R, E, n_p, m, c2;

    Hand(double R_bar, double E_bar, double kappa_eff, double m)
        : R(R_bar)
        , E(E_bar)
        , n_p(pi * 3.0 * std::pow(6.0, -1.0 / m) * std::pow(R_bar, -1.0 / m)
              * kappa_eff)
        , m(m)
        , c2(1.43 * std::exp(-0.97 / m))
    {
    }

    double
    a_p(double gamma) const
    {
      return std::sqrt(2 * c2 * R * gamma);
    }

    double
    chi(double K, double a_p) const
    {
      return 4 * pi * K * K / (n_p * n_p * std::pow(a_p, 1 + 2 / m));
    }
  };

  Hand
  du_flat_hand()
  {
    const auto mat = du_material();
    return Hand(du_radius,
                mat.youngs_modulus
                  / (1 - mat.poisson_ratio * mat.poisson_ratio),
                mat.plastic_stiffness,
                mat.plastic_exponent);
  }

  /// Piecewise-linear history, each state (gamma, history before the step)
  /// visited in order; the history is updated as a converged state.
  struct State
  {
    double         gamma;
    ContactHistory history;
  };

  std::vector<State>
  walk(const BondedElastoplasticLaw &law,
       const std::vector<double>    &turning_points,
       int                           steps)
  {
    std::vector<State> states;
    ContactHistory     h;
    for (std::size_t s = 1; s < turning_points.size(); ++s)
      for (int i = 1; i <= steps; ++i)
        {
          const double t = double(i) / steps;
          const double g
            = (1 - t) * turning_points[s - 1] + t * turning_points[s];
          states.push_back({g, h});
          h = law.updated_history(g, h);
        }
    return states;
  }
} // namespace

TEST(BondedElastoplastic, PairConstantsFollowTheMixingRulesOfSection2)
{
  const ElastoplasticMaterial m1{5e9, 0.25, 150e6, 2.0};
  const ElastoplasticMaterial m2{30e9, 0.2, 900e6, 2.0};
  const double                R1 = 220e-6, R2 = 150e-6;
  const auto law = BondedElastoplasticLaw::for_pair(m1, R1, m2, R2, 1e6, 0.01);
  const auto swapped
    = BondedElastoplasticLaw::for_pair(m2, R2, m1, R1, 1e6, 0.01);

  const double R = 1 / (1 / R1 + 1 / R2);
  const double E = 1 / ((1 - 0.25 * 0.25) / 5e9 + (1 - 0.2 * 0.2) / 30e9);
  const double kappa
    = std::pow(std::pow(150e6, -2.0) + std::pow(900e6, -2.0), -0.5);
  const Hand hand(R, E, kappa, 2.0);
  EXPECT_NEAR(law.constants().effective_radius, R, 1e-15 * R);
  EXPECT_NEAR(law.constants().effective_modulus, E, 1e-12 * E);
  EXPECT_NEAR(law.constants().plastic_coefficient, hand.n_p, 1e-12 * hand.n_p);
  EXPECT_NEAR(law.c_squared(), 1.43 * std::exp(-0.97 / 2), 1e-15);
  // The law is symmetric in the two bodies.
  for (double gamma : {1e-7, 1e-6, 5e-6})
    EXPECT_DOUBLE_EQ(law.response(gamma, 0, 0).force,
                     swapped.response(gamma, 0, 0).force);
}

TEST(BondedElastoplastic, PlasticLoadingIsTheMesarovicFleckPowerLaw)
{
  const auto law  = du_on_flat();
  const Hand hand = du_flat_hand();
  for (double gamma : {1e-9, 1e-8, du_gamma_max})
    {
      const double a = hand.a_p(gamma);
      const auto   r = law.response(gamma, 0, 0);
      EXPECT_NEAR(r.contact_radius, a, 1e-12 * a);
      EXPECT_NEAR(r.force,
                  hand.n_p * std::pow(a, 2 + 1 / hand.m),
                  1e-12 * r.force);
    }
}

TEST(BondedElastoplastic, StiffnessEqualsFiniteDifferenceAlongLoadUnloadReload)
{
  for (const bool regularized : {true, false})
    {
      const auto law = du_on_flat(0.01, regularized);
      // load, unload, reload past a_p, unload past breakage, reload.
      const std::vector<double> path{
        0, 20e-9, 12e-9, du_gamma_max, 10e-9, 22e-9};
      int checked = 0;
      for (const auto &s : walk(law, path, 500))
        {
          const double a_p     = BondedElastoplasticLaw::a_p(s.history);
          const double gamma_p = law.plastic_overlap(a_p);
          const double gamma_b = law.breakage_overlap(a_p);
          const double h       = 1e-7 * du_gamma_max;
          // Skip the kinks: onset of unloading, breakage (infinite slope).
          if (std::abs(s.gamma - gamma_p) < 1e-3 * du_gamma_max
              || (a_p > 0 && s.gamma - gamma_b < 1e-2 * du_gamma_max
                  && s.gamma < gamma_p))
            continue;
          auto P = [&](double g) {
            return law.response(g, a_p, BondedElastoplasticLaw::a_B(s.history))
              .force;
          };
          const double fd = (P(s.gamma + h) - P(s.gamma - h)) / (2 * h);
          const double exact
            = law.response(s.gamma, a_p, BondedElastoplasticLaw::a_B(s.history))
                .stiffness;
          // Normalised by the scale of the stiffness on this branch so that
          // the zero crossing at pull-off is not a 0/0.
          const double scale = std::max(
            std::abs(exact),
            law.response(std::max(s.gamma, gamma_p), a_p, 0).stiffness);
          EXPECT_LE(std::abs(fd - exact), 1e-6 * scale)
            << "gamma " << s.gamma << " a_p " << a_p << " a_B "
            << BondedElastoplasticLaw::a_B(s.history) << " regularized "
            << regularized;
          ++checked;
        }
      EXPECT_GT(checked, 1500);
    }
}

TEST(BondedElastoplastic, RegularizedForceIsContinuousAtOnsetOfUnloading)
{
  const auto   law       = du_on_flat(0.01);
  const double a_p       = law.plastic_radius(du_gamma_max);
  const double P_loading = law.response(du_gamma_max, 0, 0).force;
  for (double eps : {1e-6, 1e-9, 1e-12})
    {
      const double P = law.response(du_gamma_max * (1 - eps), a_p, a_p).force;
      EXPECT_NEAR(P, P_loading, 20 * eps * P_loading + 1e-12 * P_loading);
    }
}

TEST(BondedElastoplastic, UnregularizedForceJumpsByTheBridgeForce)
{
  const auto   law  = du_on_flat(0.01, false);
  const double a_p  = law.plastic_radius(du_gamma_max);
  const double jump = 2 * du_toughness * std::sqrt(pi) * std::pow(a_p, 1.5);
  const double P_loading = law.response(du_gamma_max, 0, 0).force;
  const double P_unloading
    = law.response(du_gamma_max * (1 - 1e-12), a_p, a_p).force;
  EXPECT_NEAR(P_loading - P_unloading, jump, 1e-6 * jump);
}

TEST(BondedElastoplastic, ForceVanishesWhereTheContactRadiusDoes)
{
  const auto   law  = du_on_flat();
  const Hand   hand = du_flat_hand();
  const double a_p  = law.plastic_radius(du_gamma_max);
  const double gamma_b
    = du_gamma_max
      - 3 * hand.n_p * std::pow(a_p, 1 + 1 / hand.m) / (4 * hand.E);
  EXPECT_NEAR(law.breakage_overlap(a_p), gamma_b, 1e-12 * du_gamma_max);
  // a = 0 and P = 0 at the breakage overlap (up to the round-off of
  // a_p^2 - recovery^2) and below it ...
  const auto at = law.response(gamma_b, a_p, a_p);
  EXPECT_LT(at.contact_radius, 1e-6 * a_p);
  EXPECT_LT(std::abs(at.force),
            1e-9 * law.response(du_gamma_max, a_p, a_p).force);
  for (double g : {gamma_b - 1e-12, gamma_b - 1e-9})
    {
      const auto r = law.response(g, a_p, a_p);
      EXPECT_EQ(r.contact_radius, 0.0);
      EXPECT_EQ(r.force, 0.0);
    }
  // ... and P -> 0 continuously as a -> 0 from above.
  const auto r = law.response(gamma_b + 1e-6 * du_gamma_max, a_p, a_p);
  EXPECT_GT(r.contact_radius, 0.0);
  EXPECT_LT(std::abs(r.force),
            1e-3 * law.response(du_gamma_max, a_p, a_p).force);
}

TEST(BondedElastoplastic, UnregularizedCriticalRadiusSatisfiesClosedForm)
{
  // For xi_B = 0 the pull-off point solves
  // (a_c/a_p)^3 = chi (3 pi / 8)^2 (1 - (a_c/a_p)^2) (Sec. 3.2).
  const auto   law     = du_on_flat(0.01, false);
  const double a_p     = law.plastic_radius(du_gamma_max);
  const double gamma_b = law.breakage_overlap(a_p);
  // Golden-section search for the most tensile force, using P only.
  double       lo = gamma_b, hi = du_gamma_max;
  const double phi = (std::sqrt(5.0) - 1) / 2;
  auto         P   = [&](double g) { return law.response(g, a_p, a_p).force; };
  for (int i = 0; i < 200; ++i)
    {
      const double x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
      (P(x1) < P(x2) ? hi : lo) = (P(x1) < P(x2) ? x2 : x1);
    }
  const double x = law.response(0.5 * (lo + hi), a_p, a_p).contact_radius / a_p;
  const double chi = du_flat_hand().chi(du_toughness, a_p);
  const double residual
    = x * x * x - chi * std::pow(3 * pi / 8, 2) * (1 - x * x);
  EXPECT_NEAR(residual, 0.0, 1e-6 * x * x * x);
  EXPECT_GT(x, 0.0);
  EXPECT_LT(x, 1.0);
}

TEST(BondedElastoplastic, ChiOfTheDuCaseUnderBothGeometricConventions)
{
  // Sphere on a rigid flat (the finite-element model of Du et al.): the
  // convention compax uses for sphere-wall contacts.
  const Hand   flat     = du_flat_hand();
  const double a_flat   = flat.a_p(du_gamma_max);
  const double chi_flat = flat.chi(du_toughness, a_flat);
  const auto   law_flat = du_on_flat();
  EXPECT_NEAR(law_flat.bonding_energy_ratio(
                law_flat.plastic_radius(du_gamma_max)),
              chi_flat,
              1e-10 * chi_flat);

  // Two identical spheres of radius R: R* = R/2, E* = E/2(1-nu^2),
  // kappa* = 2^{-1/m} kappa, with gamma_max the mutual approach.
  const auto   mat = du_material();
  const Hand   pair(du_radius / 2,
                  mat.youngs_modulus / (2 * (1 - 0.09)),
                  std::pow(2.0, -1 / 1.79) * mat.plastic_stiffness,
                  1.79);
  const double chi_pair = pair.chi(du_toughness, pair.a_p(du_gamma_max));
  const auto   law_pair = BondedElastoplasticLaw::for_pair(
    mat, du_radius, mat, du_radius, du_toughness, 0.01);
  EXPECT_NEAR(law_pair.bonding_energy_ratio(
                law_pair.plastic_radius(du_gamma_max)),
              chi_pair,
              1e-10 * chi_pair);

  // The paper prints chi = 0.0493; neither convention reproduces it (the
  // flat gives 0.0427, the pair 0.0889), which is recorded as an erratum.
  EXPECT_GT(std::abs(chi_flat / 0.0493 - 1), 0.05);
  EXPECT_GT(std::abs(chi_pair / 0.0493 - 1), 0.05);
}

TEST(BondedElastoplastic, HistoryFollowsEquation13)
{
  const auto     law = du_on_flat();
  ContactHistory h;
  // Plastic loading forms the bond: a_B = a_p = a.
  h = law.updated_history(20e-9, h);
  EXPECT_DOUBLE_EQ(BondedElastoplasticLaw::a_p(h), law.plastic_radius(20e-9));
  EXPECT_DOUBLE_EQ(BondedElastoplasticLaw::a_B(h),
                   BondedElastoplasticLaw::a_p(h));
  const ContactHistory loaded = h;
  // Elastic unloading leaves both unchanged, and evaluate() never touches
  // the history.
  h = law.updated_history(15e-9, h);
  EXPECT_EQ(h, loaded);
  (void)law.evaluate(12e-9, h);
  EXPECT_EQ(h, loaded);
  // Unloading past breakage breaks the bridge, keeps the plastic radius.
  h = law.updated_history(law.breakage_overlap(BondedElastoplasticLaw::a_p(h))
                            - 1e-10,
                          h);
  EXPECT_DOUBLE_EQ(BondedElastoplasticLaw::a_p(h),
                   BondedElastoplasticLaw::a_p(loaded));
  EXPECT_EQ(BondedElastoplasticLaw::a_B(h), 0.0);
  // Reloading below gamma_p: no bridge force, the force is the elastic one.
  const double g = 19e-9;
  EXPECT_GT(law
              .response(g,
                        BondedElastoplasticLaw::a_p(h),
                        BondedElastoplasticLaw::a_B(h))
              .force,
            law
              .response(g,
                        BondedElastoplasticLaw::a_p(h),
                        BondedElastoplasticLaw::a_p(h))
              .force);
  // Reloading past a_p renews plastic loading and the bond.
  h = law.updated_history(25e-9, h);
  EXPECT_DOUBLE_EQ(BondedElastoplasticLaw::a_p(h), law.plastic_radius(25e-9));
  EXPECT_DOUBLE_EQ(BondedElastoplasticLaw::a_B(h),
                   BondedElastoplasticLaw::a_p(h));
}

TEST(BondedElastoplastic, ForceResolutionDecidesWhetherEquation13Applies)
{
  // History update = resolved-forces against every-contact: a contact that
  // loads plastically with |P| at or below the resolution keeps its virgin
  // internal variables; resolution 0 (every-contact) applies Eq. 13, a_B =
  // a_p = a(gamma).
  const ParticleLaw law   = du_on_flat();
  const double      gamma = 5e-9;
  const double      P     = std::abs(law_response(law, gamma, {}).force);
  ASSERT_GT(P, 0.0);
  ContactHistory resolved;
  BondChanges    changes;
  update_history(law, gamma, resolved, changes, 1.01 * P);
  EXPECT_EQ(resolved, ContactHistory{});
  EXPECT_EQ(changes.formed, 0u);

  ContactHistory every;
  update_history(law, gamma, every, changes, 0.0);
  EXPECT_DOUBLE_EQ(BondedElastoplasticLaw::a_p(every),
                   du_on_flat().plastic_radius(gamma));
  EXPECT_DOUBLE_EQ(BondedElastoplasticLaw::a_B(every),
                   BondedElastoplasticLaw::a_p(every));
  EXPECT_EQ(changes.formed, 1u);

  // A resolution below |P| does not hold the update back.
  ContactHistory above;
  update_history(law, gamma, above, changes, 0.99 * P);
  EXPECT_EQ(above, every);
}

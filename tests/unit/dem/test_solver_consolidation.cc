#include "dem/die/die_compaction.h"
#include "dem/die/die_setup.h"
#include "dem/numbers.h"
#include "dem/solver/consolidation.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/trust_region_newton.h"
#include "tests/support/deposited_die.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

/// The force the solvers evaluate (contact_response of the particle law,
/// a^{1/m} by sqrt for m = 2) equals Gonzalez 2018 Eqs. 3-4 written out
/// with pow, on every branch: virgin, plastic reloading, elastic unloading
/// with and without a regularized bridge, separated; for m = 2 and m = 3.
TEST(SolverConsolidation, SolverResponseEqualsEquations3And4)
{
  for (const double m : {2.0, 3.0})
    {
      const ElastoplasticMaterial mat{material1::E,
                                      material1::nu,
                                      material1::kappa,
                                      m};
      const double                xi  = 0.01;
      const auto                  law = BondedElastoplasticLaw::for_pair(
        mat, material1::R, mat, material1::R, material1::K_Ic, xi, true);
      const auto  &k         = law.constants();
      const double c2R       = law.c_squared() * k.effective_radius;
      const double n_p       = k.plastic_coefficient;
      const double a_p       = law.plastic_radius(2e-6);
      const auto   eq3_and_4 = [&](double gamma, ContactHistory h) {
        if (gamma >= BondedElastoplasticLaw::a_p(h)
                       * BondedElastoplasticLaw::a_p(h) / (2.0 * c2R))
          return gamma > 0.0
                     ? n_p * std::pow(std::sqrt(2.0 * c2R * gamma), 2.0 + 1.0 / m)
                     : 0.0;
        const double alpha
          = 4.0 * k.effective_modulus
            / (3.0 * n_p * std::pow(BondedElastoplasticLaw::a_p(h), 1.0 / m));
        const double recovery
          = alpha
            * (BondedElastoplasticLaw::a_p(h) * BondedElastoplasticLaw::a_p(h)
                 / (2.0 * c2R)
               - gamma);
        if (recovery >= BondedElastoplasticLaw::a_p(h))
          return 0.0;
        const double a = std::sqrt(BondedElastoplasticLaw::a_p(h)
                                     * BondedElastoplasticLaw::a_p(h)
                                   - recovery * recovery);
        const double x = a / BondedElastoplasticLaw::a_p(h);
        double       P = 2.0 * n_p / pi
                   * std::pow(BondedElastoplasticLaw::a_p(h), 2.0 + 1.0 / m)
                   * (std::asin(x) - x * std::sqrt(1.0 - x * x));
        if (BondedElastoplasticLaw::a_B(h) > 0.0
            && a < BondedElastoplasticLaw::a_B(h))
          P -= 2.0 * material1::K_Ic * std::sqrt(pi) * (1.0 + xi) * (1.0 + xi)
               * std::pow(a, 1.5) * (BondedElastoplasticLaw::a_B(h) - a)
               / ((1.0 + xi) * BondedElastoplasticLaw::a_B(h) - a);
        return P;
      };
      for (const ContactHistory h : {ContactHistory{0.0, 0.0},
                                     ContactHistory{a_p, 0.0},
                                     ContactHistory{a_p, a_p}})
        for (double gamma = -1e-6; gamma <= 4e-6; gamma += 1.7e-8)
          {
            const double ref = eq3_and_4(gamma, h);
            const double P = contact_response(ParticleLaw(law), gamma, h).force;
            EXPECT_NEAR(P, ref, 1e-12 * std::abs(ref) + 1e-300)
              << "m = " << m << ", a_p = " << BondedElastoplasticLaw::a_p(h)
              << ", a_B = " << BondedElastoplasticLaw::a_B(h)
              << ", gamma = " << gamma;
          }
    }
}

/// A loose deposit consolidated to jamming: the relaxed bed is in
/// equilibrium to the relaxation tolerance (recomputed independently of
/// the relaxation), the punches carry equal and opposite forces (no
/// friction, no gravity: the die wall acts radially only), the upper punch
/// carries at least the jamming pressure, the jamming density lies below
/// random close packing of frictionless spheres (~0.64), and no internal
/// variable changed (consolidation never updates histories).
TEST(SolverConsolidation, LooseDepositJamsWithBalancedPunches)
{
  Bed                bed   = compax::testing::deposited_die(300, 3.5e-3, 5);
  const ContactModel model = material1::contact_model();
  const double       rho0  = bed.relative_density();
  EXPECT_LT(rho0, 0.55);

  ConsolidationOptions      opts;
  Consolidation             c(opts);
  const ConsolidationResult r = c.run(bed, model, 0.8);
  ASSERT_TRUE(r.jammed);
  EXPECT_FALSE(r.failed);
  EXPECT_GT(bed.relative_density(), rho0);
  EXPECT_LT(bed.relative_density(), 0.66);

  ContactAssembler  a;
  Eigen::VectorXd   F;
  const ContactSums s    = a.residual(bed, model, F);
  const double      area = bed.walls.punch_area();
  EXPECT_GE(s.wall_force[int(Wall::upper_punch)], opts.jamming_pressure * area);
  EXPECT_LE(max_particle_norm(F), opts.relative_tolerance * s.mean_force);
  // Newton's third law over the whole bed: the axial forces on the
  // particles sum to the punch forces' difference.
  double fz = 0.0;
  for (Eigen::Index i = 2; i < F.size(); i += 3)
    fz += F[i];
  EXPECT_NEAR(s.wall_force[int(Wall::upper_punch)]
                - s.wall_force[int(Wall::lower_punch)],
              fz,
              1e-9 * s.wall_force[int(Wall::upper_punch)]);
  // ... hence bounded by N times the largest out-of-balance force.
  EXPECT_LE(std::abs(fz),
            static_cast<double>(bed.particles.size()) * opts.relative_tolerance
              * s.mean_force);
  for (const PairContact &p : bed.contacts.pairs)
    {
      EXPECT_EQ(BondedElastoplasticLaw::a_p(p.history), 0.0);
      EXPECT_EQ(BondedElastoplasticLaw::a_B(p.history), 0.0);
    }
}

/// Regression of the whole path on ~1000 particles of Material 1: the
/// ballistic deposit consolidates to jamming, then static load steps reach
/// in-die relative density 0.85. At every converged state every particle's
/// net force is within the solver tolerance and the punch forces balance.
TEST(SolverConsolidation, ThousandParticlesReach085)
{
  Bed                bed   = compax::testing::deposited_die(1000,
                                           10e-3 * std::cbrt(1000.0 / 6512.0),
                                           1);
  const ContactModel model = material1::contact_model();
  DieProtocol        protocol;
  protocol.compaction_targets
    = density_targets(bed.relative_density(), 0.85, 21);
  protocol.consolidate = true; // the frozen-history consolidation
  DieCompaction      die(bed, model, protocol);
  std::ostringstream csv;
  die.set_output(&csv, nullptr);
  ASSERT_NO_THROW(die.run());
  EXPECT_FALSE(die.failed());
  EXPECT_GT(die.jamming_density(), 0.5);
  EXPECT_LT(die.jamming_density(), 0.66);
  EXPECT_NEAR(die.bed().relative_density(), 0.85, 1e-9);

  const double tol = EquilibriumOptions{}.force_tolerance;
  for (const DieRecord &r : die.records())
    {
      if (r.step == 0)
        continue; // the deposit as filled
      EXPECT_LE(r.residual, tol) << r.step;
      EXPECT_GT(r.upper_punch_force, 0.0) << r.step;
      // Pair forces cancel in the sum of the out-of-balance forces, which
      // leaves F_u - F_l: bounded by N times the largest residual.
      EXPECT_LE(std::abs(r.upper_punch_force - r.lower_punch_force),
                1000.0 * r.residual * r.mean_contact_force
                  + 1e-12 * r.upper_punch_force)
        << r.step;
    }
  Bed               final_bed = die.bed();
  ContactAssembler  a;
  Eigen::VectorXd   F;
  const ContactSums s = a.residual(final_bed, model, F);
  EXPECT_LE(max_particle_norm(F), tol * s.mean_force);
}

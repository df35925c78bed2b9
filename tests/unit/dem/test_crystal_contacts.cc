// Granular crystals of Gonzalez & Cuitino 2012, Sec. 4.1, checked against
// values derived here: Tatara's series (Eq. 12) and the discrepancy of Eq.
// (17) for the 1-D chain, Hertz closed forms of the lattices, the
// geometric onset of the BCC second contacts, the reduced symmetric
// equations of the BCC crystal under hydrostatic compaction, the limit
// point of the chain, and the symmetry of the cubic lattice.

#include "dem/contact/nonlocal_hertz.h"
#include "dem/crystals/crystal_compaction.h"
#include "dem/crystals/crystal_contacts.h"
#include "dem/crystals/granular_crystal.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace compax::dem;

  constexpr double pi = 3.14159265358979323846;

  // Rubber spheres of Sec. 3.
  const CrystalMaterial rubber{0.01, 1.85e6, 0.46};

  // Eq. (9) for two identical spheres, written out here.
  double
  n_H_spheres(const CrystalMaterial &m)
  {
    const double inverse = 0.75 * 2 * (1 - m.poisson_ratio * m.poisson_ratio)
                           / m.youngs_modulus * std::sqrt(2 / m.radius);
    return 1 / inverse;
  }

  // Eq. (5) per unit force, written out here.
  double
  eq5(double theta, const CrystalMaterial &m)
  {
    const double nu = m.poisson_ratio, s = std::sin(theta / 2);
    return (1 + nu) / (4 * pi * m.radius * m.youngs_modulus)
           * (-2 * (1 - nu) - 2 * (1 - 2 * nu) * s + (7 - 8 * nu) * s * s) / s;
  }

  CrystalResponse
  solve(CrystalConfiguration   configuration,
        const CrystalMaterial &m,
        CrystalFormulation     formulation,
        double                 epsilon,
        double                 scale = 1.0)
  {
    CrystalContactOptions options;
    options.nonlocal_scale = scale;
    CrystalContacts contacts(make_crystal_lattice(configuration, m.radius),
                             m,
                             formulation,
                             options);
    return contacts.solve(crystal_cell_strains(configuration, epsilon, 0.04));
  }
} // namespace

TEST(CrystalChain, FollowsTatarasSeriesEq12)
{
  // Sphere-sphere contacts of the chain, each sphere loaded at its far
  // pole: Eq. (11) with two spheres gives 1/n_NL.
  for (const double nu : {0.0, 0.3, 0.46})
    {
      const CrystalMaterial m{0.01, 1.85e6, nu};
      const double          n    = n_H_spheres(m);
      const double          n_NL = 1
                          / (2 * (1 + nu) * (3 - 2 * nu)
                             / (4 * pi * m.radius * m.youngs_modulus));
      for (const double epsilon : {1e-4, 1e-3})
        {
          const double gamma = 2 * m.radius * epsilon;
          const double F     = solve(CrystalConfiguration::chain_1d,
                                 m,
                                 CrystalFormulation::nonlocal,
                                 epsilon)
                             .face_force[2];
          const double series = n * std::pow(gamma, 1.5)
                                + 1.5 * n * n / n_NL * gamma * gamma
                                + 21.0 / 8 * std::pow(n, 3) / (n_NL * n_NL)
                                    * std::pow(gamma, 2.5);
          // The next term of the series (x = (1 + beta x)^{3/2} expanded to
          // third order): 5 n^4 / n_NL^3 gamma^3.
          const double next
            = 5 * std::pow(n / n_NL, 3) * n * gamma * gamma * gamma;
          EXPECT_NEAR(F, series + next, 0.2 * next) << nu << ' ' << epsilon;
        }
    }
}

TEST(CrystalChain, DiscrepancyFollowsEq17)
{
  for (const double nu : {0.1, 0.46})
    {
      const CrystalMaterial m{0.01, 1.85e6, nu};
      const double          k = (3 - 2 * nu) / (1 - nu);
      for (const double epsilon : {1e-5, 1e-4})
        {
          const double hertz = solve(CrystalConfiguration::chain_1d,
                                     m,
                                     CrystalFormulation::hertz,
                                     epsilon)
                                 .face_force[2];
          const double nonlocal = solve(CrystalConfiguration::chain_1d,
                                        m,
                                        CrystalFormulation::nonlocal,
                                        epsilon)
                                    .face_force[2];
          const double D   = (nonlocal - hertz) / hertz;
          const double D17 = k / (2 * pi) * std::sqrt(epsilon)
                             + 7 / (24 * pi * pi) * k * k * epsilon;
          // O(eps^{3/2}) remainder: 5 beta^3 with beta = k sqrt(eps)/(3 pi).
          const double remainder
            = 5 * std::pow(k / (3 * pi), 3) * std::pow(epsilon, 1.5);
          EXPECT_NEAR(D - D17, remainder, 0.1 * remainder)
            << nu << ' ' << epsilon;
        }
    }
}

TEST(CrystalChain, EqualsTheChainBetweenPlates)
{
  // N spheres between rigid plates at approach Delta = 2 N R eps carry the
  // force of the periodic chain at deformation eps.
  const double epsilon = 0.05;
  const double F       = solve(CrystalConfiguration::chain_1d,
                         rubber,
                         CrystalFormulation::nonlocal,
                         epsilon)
                     .face_force[2];
  for (const unsigned int N : {1u, 4u})
    {
      const ChainSolution plates
        = solve_chain_between_plates(N,
                                     2 * N * rubber.radius * epsilon,
                                     rubber.radius,
                                     rubber.youngs_modulus,
                                     rubber.poisson_ratio);
      ASSERT_TRUE(plates.converged);
      EXPECT_NEAR(F, plates.force, 1e-10 * F);
    }
}

TEST(CrystalChain, LimitPointOfTheNonlocalFormulation)
{
  // Per sphere-plate half of a contact, Delta / 2N = s - kappa s^{3/2}
  // with kappa = c n_H,wall has no root beyond 4 / (27 kappa^2); for the
  // chain gamma_w = R eps.
  const CrystalMaterial m{0.01, 1.85e6, 0.49};
  const double          nu = m.poisson_ratio;
  const double          c
    = (1 + nu) * (3 - 2 * nu) / (4 * pi * m.radius * m.youngs_modulus);
  const double n_wall
    = 4.0 / 3 * m.youngs_modulus / (1 - nu * nu) * std::sqrt(m.radius);
  const double limit = 4 / (27 * c * c * n_wall * n_wall) / m.radius;
  ASSERT_LT(limit, 0.95);

  CrystalPathOptions options;
  options.max_strain     = 0.95;
  options.steps          = 50;
  const CrystalPath path = compute_crystal_path(CrystalConfiguration::chain_1d,
                                                m,
                                                CrystalFormulation::nonlocal,
                                                options);
  ASSERT_FALSE(path.complete());
  EXPECT_NEAR(path.points.back().strain, limit, 2e-3 * limit);
  EXPECT_LE(path.points.back().strain, path.failure_strain);
  EXPECT_TRUE(compute_crystal_path(CrystalConfiguration::chain_1d,
                                   m,
                                   CrystalFormulation::hertz,
                                   options)
                .complete());
}

TEST(CrystalLattices, NonlocalTermsOffIsHertz)
{
  for (const auto configuration : all_crystal_configurations())
    for (const double epsilon : {0.02, 0.08})
      {
        const auto off = solve(
          configuration, rubber, CrystalFormulation::nonlocal, epsilon, 0.0);
        const auto hertz
          = solve(configuration, rubber, CrystalFormulation::hertz, epsilon);
        const auto full
          = solve(configuration, rubber, CrystalFormulation::nonlocal, epsilon);
        ASSERT_TRUE(off.converged && hertz.converged && full.converged);
        EXPECT_NEAR(off.face_force[2],
                    hertz.face_force[2],
                    1e-14 * hertz.face_force[2]);
        EXPECT_EQ(off.coordination, hertz.coordination);
        // Confined crystals are stiffer with the nonlocal terms.
        EXPECT_GT(full.face_force[2], hertz.face_force[2])
          << crystal_configuration_name(configuration);
      }
}

TEST(CrystalLattices, SimpleCubicHertzClosedForm)
{
  // One contact per (2R)^2 of cross-section, overlap 2 R eps; no lateral
  // force under Hertz.
  const double R = rubber.radius, n = n_H_spheres(rubber);
  for (const double epsilon : {0.01, 0.1})
    {
      const auto   r = solve(CrystalConfiguration::cubic_3d,
                           rubber,
                           CrystalFormulation::hertz,
                           epsilon);
      const double P = n * std::pow(2 * R * epsilon, 1.5);
      EXPECT_NEAR(r.stress(2, 2), P / (4 * R * R), 1e-12 * P / (R * R));
      EXPECT_NEAR(r.face_force[2], P, 1e-12 * P);
      EXPECT_EQ(r.face_force[0], 0.0);
      EXPECT_EQ(r.face_force[1], 0.0);
      EXPECT_EQ(r.coordination, 2u);
      EXPECT_NEAR(r.relative_density, pi / 6 / (1 - epsilon), 1e-14);
    }
}

TEST(CrystalLattices, CubicLateralReactionsAreEqual)
{
  for (const double nu : {0.0, 0.25, 0.46})
    {
      const CrystalMaterial m{0.01, 1.85e6, nu};
      const auto            r = solve(CrystalConfiguration::cubic_3d,
                           m,
                           CrystalFormulation::nonlocal,
                           0.07);
      ASSERT_TRUE(r.converged);
      EXPECT_GT(r.face_force[0], 0.0);
      EXPECT_NEAR(r.face_force[0], r.face_force[1], 1e-12 * r.face_force[0]);
      // Off-diagonal stresses vanish by the mirror symmetries.
      EXPECT_NEAR(r.stress(0, 2), 0.0, 1e-12 * r.stress(2, 2));
    }
}

TEST(CrystalLattices, HertzLoadsOfInclinedContactsByCounting)
{
  // Rotated square and close-packed layers: per particle column of the
  // conventional cell face, two inclined contacts cross a horizontal plane,
  // each with vertical component P sin(alpha).
  const double R = rubber.radius, n = n_H_spheres(rubber), epsilon = 0.06;
  struct Layer
  {
    CrystalConfiguration configuration;
    double               half_width, height; // neighbour at (+-w, h)
  };
  for (const Layer &l :
       {Layer{CrystalConfiguration::square_2d_rotated,
              std::sqrt(2.0) * R,
              std::sqrt(2.0) * R},
        Layer{CrystalConfiguration::hexagonal_2d, R, std::sqrt(3.0) * R}})
    {
      const double h = l.height * (1 - epsilon);
      const double d = std::hypot(l.half_width, h);
      const double P = n * std::pow(2 * R - d, 1.5);
      const auto   r
        = solve(l.configuration, rubber, CrystalFormulation::hertz, epsilon);
      EXPECT_NEAR(r.face_force[2], 2 * P * h / d, 1e-12 * P);
    }
}

TEST(CrystalBcc, RelativeDensityIsEq19)
{
  for (const double epsilon : {0.0, 0.05, 0.2})
    {
      const auto hydro
        = make_crystal_lattice(CrystalConfiguration::bcc_hydrostatic, 0.01);
      EXPECT_NEAR(hydro.relative_density(crystal_cell_strains(
                    CrystalConfiguration::bcc_hydrostatic, epsilon, 0)),
                  pi * std::sqrt(3.0) / (8 * std::pow(1 - epsilon, 3)),
                  1e-14);
      EXPECT_NEAR(hydro.relative_density(crystal_cell_strains(
                    CrystalConfiguration::bcc_die, epsilon, 0)),
                  pi * std::sqrt(3.0) / (8 * (1 - epsilon)),
                  1e-14);
    }
}

TEST(CrystalBcc, HertzSecondContactsAreGeometric)
{
  // Nearest neighbours at sqrt(3)/2 a, second neighbours at a = 4R/sqrt(3).
  // Hydrostatic: a (1 - eps) = 2R; die: the compressed edge c = 2R. The
  // lateral second neighbours (die) stay at a > 2R and the third shell
  // (sqrt(2) a) is far: no third contacts.
  const double stretch = std::sqrt(3.0) / 2; // 2R / a
  const double rho0    = pi * std::sqrt(3.0) / 8;
  for (const double nu : {0.2, 0.45})
    {
      const CrystalMaterial m{0.01, 1.85e6, nu};
      CrystalPathOptions    options;
      options.steps = 120;
      for (const auto configuration : {CrystalConfiguration::bcc_hydrostatic,
                                       CrystalConfiguration::bcc_die})
        {
          const bool hydrostatic
            = configuration == CrystalConfiguration::bcc_hydrostatic;
          options.max_strain = crystal_strain_at_density(configuration, 1.1, 0);
          const CrystalPath path = compute_crystal_path(
            configuration, m, CrystalFormulation::hertz, options);
          ASSERT_TRUE(path.complete());
          const double expected
            = hydrostatic ? rho0 / std::pow(stretch, 3) : rho0 / stretch;
          EXPECT_NEAR(path.formation_density(2), expected, 1e-10);
          EXPECT_NEAR(path.formation_density(1), rho0, 1e-10);
          EXPECT_EQ(path.formations[0].contacts, 8u);
          EXPECT_EQ(path.formations[1].contacts, hydrostatic ? 6u : 2u);
          EXPECT_TRUE(std::isnan(path.formation_density(3)));
        }
    }
}

TEST(CrystalBcc, NonlocalSecondContactsOfTheReducedEquations)
{
  // Hydrostatic compaction keeps the angles: the 8 nearest neighbours
  // carry one force P with gamma_NL = 2 [c(pi) + 3 c(acos 1/3) +
  // 3 c(acos -1/3)] P, both particles of a contact contributing, and the
  // second neighbours (along <100>) see gamma_NL = 2 [4 c(acos 1/sqrt3) +
  // 4 c(acos -1/sqrt3)] P. Second contacts form where
  // gamma_2 + gamma_NL,2 = 0.
  for (const double nu : {0.3, 0.45})
    {
      const CrystalMaterial m{0.01, 1.85e6, nu};
      const double R = m.radius, a = 4 * R / std::sqrt(3.0), n = n_H_spheres(m);
      const double k1 = 2
                        * (eq5(pi, m) + 3 * eq5(std::acos(1 / 3.0), m)
                           + 3 * eq5(std::acos(-1 / 3.0), m));
      const double k2 = 2 * 4
                        * (eq5(std::acos(1 / std::sqrt(3.0)), m)
                           + eq5(std::acos(-1 / std::sqrt(3.0)), m));
      EXPECT_EQ(k2 > 0, nu > 0.4);
      const auto gap = [&](double epsilon) {
        const double g1 = 2 * R - std::sqrt(3.0) / 2 * a * (1 - epsilon);
        double       P  = 0;
        for (int i = 0; i < 2000; ++i)
          P = n * std::pow(g1 + k1 * P, 1.5);
        return 2 * R - a * (1 - epsilon) + k2 * P;
      };
      double lo = 0, hi = 0.145;
      ASSERT_LT(gap(lo), 0);
      ASSERT_GT(gap(hi), 0);
      for (int i = 0; i < 100; ++i)
        (gap(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
      const double expected = pi * std::sqrt(3.0) / (8 * std::pow(1 - hi, 3));

      CrystalPathOptions options;
      options.steps = 60;
      options.max_strain
        = crystal_strain_at_density(CrystalConfiguration::bcc_hydrostatic,
                                    1.1,
                                    0);
      const CrystalPath path
        = compute_crystal_path(CrystalConfiguration::bcc_hydrostatic,
                               m,
                               CrystalFormulation::nonlocal,
                               options);
      EXPECT_NEAR(path.formation_density(2), expected, 1e-9) << nu;
      EXPECT_EQ(path.formations.at(1).contacts, 6u);
    }
}

TEST(CrystalLattices, AllocationFreeResolveGivesTheSameForces)
{
  // Solving twice at the same strain, with other strains in between,
  // reproduces the forces: the fixed point starts from gamma_NL = 0.
  CrystalContacts contacts(make_crystal_lattice(CrystalConfiguration::bcc_die,
                                                rubber.radius),
                           rubber,
                           CrystalFormulation::nonlocal);
  const Eigen::Vector3d strains(0, 0, 0.15);
  const auto            first = contacts.solve(strains);
  contacts.solve(Eigen::Vector3d(0, 0, 0.25));
  const auto second = contacts.solve(strains);
  EXPECT_EQ(first.face_force, second.face_force);
  EXPECT_EQ(contacts.neighbours().size() % 2, 0u);
}

// Nonlocal Hertz law and Algorithm 1 of Gonzalez & Cuitino 2012, checked
// against Hertz theory, finite differences, the paper's series (Eqs. 12, 17)
// re-derived here, and a residual of the fixed point computed independently.

#include "dem/contact/hertz.h"
#include "dem/contact/nonlocal_hertz.h"
#include "dem/contact/pair_properties.h"
#include "dem/nonlocal/nonlocal_contact_network.h"
#include "dem/numbers.h"
#include "elastic_sphere.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>
#include <random>
#include <vector>

namespace
{
  using namespace compax::dem;

  using namespace compax::dem::contact_test;

  // Two different materials; the rigid flat is rigid_flat.
  const ElasticSphere sphere_a{100e-6, 5.0e9, 0.30};
  const ElasticSphere sphere_b{150e-6, 8.0e9, 0.42};

  // Eq. (9), written out here.
  double
  hertz_coefficient(const ElasticSphere &m1, const ElasticSphere &m2)
  {
    const double inverse
      = 0.75 * ((1 - m1.nu * m1.nu) / m1.E + (1 - m2.nu * m2.nu) / m2.E)
        * std::sqrt(1 / m1.R + 1 / m2.R);
    return 1.0 / inverse;
  }

  // The network's local law with Hertz coefficient n_H [N/m^{3/2}]:
  // n_H = 4/3 E sqrt(R) with R = 1 m, E = 3/4 n_H.
  ParticleLaw
  hertz_law(const double n_H)
  {
    return HertzLaw(1.0, 0.75 * n_H);
  }

  // Eq. (5), written out here.
  double
  eq5(double P, double theta, const ElasticSphere &m)
  {
    if (std::isinf(m.R))
      return 0.0;
    const double s = std::sin(theta / 2);
    return (1 + m.nu) / (4 * pi * m.R * m.E) * P
           * (-2 * (1 - m.nu) - 2 * (1 - 2 * m.nu) * s + (7 - 8 * m.nu) * s * s)
           / s;
  }

  // Least-squares slope of log y against log x.
  double
  log_log_slope(const std::vector<double> &x, const std::vector<double> &y)
  {
    double       sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = x.size();
    for (std::size_t i = 0; i < x.size(); ++i)
      {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
      }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
  }

  TEST(NonlocalHertz, ReducesToHertzWithoutNonlocalOverlap)
  {
    for (const ElasticSphere &other : {sphere_b, rigid_flat})
      {
        const NonlocalHertzLaw law = NonlocalHertzLaw::for_pair(
          sphere_a.R, sphere_a.E, sphere_a.nu, other.R, other.E, other.nu);
        const HertzLaw hertz = HertzLaw::for_pair(
          sphere_a.R, sphere_a.E, sphere_a.nu, other.R, other.E, other.nu);
        EXPECT_EQ(law.name(), "nonlocal-hertz");
        for (const double g : {-1e-6, 0.0, 1e-9, 3e-7, 2e-6, 1e-5})
          {
            const ContactResponse r = law.evaluate(g, {}, ContactContext{});
            const ContactResponse h = hertz.evaluate(g, {});
            EXPECT_NEAR(r.force, h.force, 1e-14 * std::abs(h.force));
            EXPECT_NEAR(r.stiffness, h.stiffness, 1e-14 * h.stiffness);
            EXPECT_NEAR(r.contact_radius,
                        h.contact_radius,
                        1e-14 * h.contact_radius);
          }
      }
  }

  TEST(NonlocalHertz, ForceStiffnessAndRadiusWithNonlocalOverlap)
  {
    for (const ElasticSphere &other : {sphere_b, rigid_flat})
      {
        const NonlocalHertzLaw law = NonlocalHertzLaw::for_pair(
          sphere_a.R, sphere_a.E, sphere_a.nu, other.R, other.E, other.nu);
        const double n_H = hertz_coefficient(sphere_a, other);
        const double R   = 1 / (1 / sphere_a.R + 1 / other.R);
        const double E   = 1
                         / ((1 - sphere_a.nu * sphere_a.nu) / sphere_a.E
                            + (1 - other.nu * other.nu) / other.E);
        for (const double g : {1e-7, 1e-6, 5e-6})
          for (const double g_nl : {0.4 * g, -0.3 * g, 2.0 * g})
            {
              ContactContext context;
              context.nonlocal_overlap = g_nl;
              const ContactResponse r  = law.evaluate(g, {}, context);
              // Eq. (10).
              EXPECT_NEAR(r.force,
                          n_H * std::pow(g + g_nl, 1.5),
                          1e-13 * r.force);
              // Eq. (8): a^3 = 3 P R / (4 E).
              EXPECT_NEAR(std::pow(r.contact_radius, 3),
                          3 * r.force * R / (4 * E),
                          1e-12 * std::pow(r.contact_radius, 3));
              // Exact derivative at fixed gamma_NL vs central difference.
              const double h  = 1e-5 * (g + g_nl);
              const double fd = (law.evaluate(g + h, {}, context).force
                                 - law.evaluate(g - h, {}, context).force)
                                / (2 * h);
              EXPECT_NEAR(r.stiffness, fd, 1e-6 * r.stiffness);
            }
        // Separated once gamma + gamma_NL <= 0, even with gamma > 0.
        ContactContext context;
        context.nonlocal_overlap = -2e-6;
        EXPECT_EQ(law.evaluate(1e-6, {}, context).force, 0.0);
        EXPECT_EQ(law.evaluate(1e-6, {}, context).stiffness, 0.0);
      }
  }

  TEST(NonlocalHertz, HistoryIsUnchanged)
  {
    const NonlocalHertzLaw law(50e-6, 3e9);
    ContactHistory         history{{1e-6, 2e-6}};
    const ContactHistory   copy = history;
    law.evaluate(1e-6, history, ContactContext{});
    EXPECT_EQ(history, copy);
    EXPECT_EQ(law.updated_history(1e-5, history, ContactContext{}), copy);
  }

  TEST(NonlocalHertz, Eq11IsEq5AtThetaPi)
  {
    for (const ElasticSphere &m :
         {sphere_a, sphere_b, ElasticSphere{0.01, 1.85e6, 0.46}})
      {
        const double F = 0.37;
        // Eq. (11) for one sphere.
        const double eq11
          = F * (1 + m.nu) * (3 - 2 * m.nu) / (4 * pi * m.R * m.E);
        EXPECT_NEAR(nonlocal_displacement(F, pi, m.R, m.E, m.nu),
                    eq11,
                    1e-14 * eq11);
        EXPECT_NEAR(nonlocal_displacement_derivative(pi, m.R, m.E, m.nu),
                    eq11 / F,
                    1e-14 * eq11 / F);
        EXPECT_NEAR(eq5(F, pi, m), eq11, 1e-14 * eq11);
        // Eq. (14): two forces at theta = pi/2.
        const double eq14
          = F * (1 + m.nu)
            * (3 * std::sqrt(2.0) - 4 - 4 * std::sqrt(2.0) * m.nu + 8 * m.nu)
            / (4 * pi * m.R * m.E);
        EXPECT_NEAR(2 * nonlocal_displacement(F, pi / 2, m.R, m.E, m.nu),
                    eq14,
                    1e-13 * std::abs(eq14));
      }
    // A rigid body induces nothing.
    EXPECT_EQ(nonlocal_displacement(1.0, pi, rigid, rigid, 0.3), 0.0);
  }

  TEST(NonlocalHertz, DisplacementDerivativeIsFiniteDifference)
  {
    for (const double theta : {0.4, 1.0, pi / 2, 2.5, pi})
      {
        const double P = 2.0, dP = 1e-3;
        const double fd
          = (nonlocal_displacement(
               P + dP, theta, sphere_b.R, sphere_b.E, sphere_b.nu)
             - nonlocal_displacement(
               P - dP, theta, sphere_b.R, sphere_b.E, sphere_b.nu))
            / (2 * dP);
        const double d = nonlocal_displacement_derivative(theta,
                                                          sphere_b.R,
                                                          sphere_b.E,
                                                          sphere_b.nu);
        EXPECT_NEAR(d, fd, 1e-9 * std::abs(d));
        EXPECT_NEAR(d, eq5(1.0, theta, sphere_b), 1e-13 * std::abs(d));
      }
  }

  // Eq. (12): the self-consistent Tatara force agrees with the series
  // through gamma^{5/2}; the remainder is O(gamma^3). The gamma^3
  // coefficient, from F = n_H gamma^{3/2} f with f = (1 + e f)^{3/2},
  // e = n_H gamma^{1/2} / n_NL, is 5 n_H^4 / n_NL^3.
  TEST(NonlocalHertz, TataraReproducesSeriesOfEq12)
  {
    for (const ElasticSphere &other : {sphere_b, sphere_a, rigid_flat})
      {
        const ElasticSphere &m1  = sphere_a;
        const double         n_H = hertz_coefficient(m1, other);
        double               inverse_n_NL
          = (1 + m1.nu) * (3 - 2 * m1.nu) / (4 * pi * m1.R * m1.E);
        if (!std::isinf(other.R))
          inverse_n_NL += (1 + other.nu) * (3 - 2 * other.nu)
                          / (4 * pi * other.R * other.E);
        const double n_NL = 1 / inverse_n_NL;
        const double R    = 1 / (1 / m1.R + 1 / other.R);

        std::vector<double> gammas, errors;
        for (double g = 1e-5 * R; g <= 1.01e-3 * R; g *= std::sqrt(10.0))
          {
            const TataraSolution s = solve_tatara_two_spheres(
              g, m1.R, m1.E, m1.nu, other.R, other.E, other.nu);
            ASSERT_TRUE(s.converged);
            EXPECT_NEAR(s.n_H, n_H, 1e-13 * n_H);
            EXPECT_NEAR(s.n_NL, n_NL, 1e-13 * n_NL);
            // Self-consistency: Eq. (10) with gamma_NL of Eq. (11).
            EXPECT_NEAR(s.nonlocal_overlap,
                        s.force / n_NL,
                        1e-13 * s.nonlocal_overlap);
            EXPECT_NEAR(s.force,
                        n_H * std::pow(g + s.nonlocal_overlap, 1.5),
                        1e-13 * s.force);
            const double series = n_H * std::pow(g, 1.5)
                                  + 1.5 * n_H * n_H / n_NL * g * g
                                  + 21.0 / 8.0 * std::pow(n_H, 3)
                                      / (n_NL * n_NL) * std::pow(g, 2.5);
            gammas.push_back(g);
            errors.push_back(s.force - series);
            // Remainder against its leading term 5 n_H^4/n_NL^3 gamma^3.
            const double next
              = 5 * std::pow(n_H, 4) / std::pow(n_NL, 3) * std::pow(g, 3);
            EXPECT_NEAR(errors.back() / next, 1.0, 0.05) << "gamma = " << g;
          }
        const double slope = log_log_slope(gammas, errors);
        EXPECT_NEAR(slope, 3.0, 0.02);
      }
  }

  // Eq. (17): discrepancy of the 1-D chain, with epsilon = Delta / (2 N R);
  // the remainder is O(epsilon^{3/2}), with coefficient 5 c^3,
  // c = (3-2nu)/(3 pi (1-nu)), from the same series as above.
  TEST(NonlocalHertz, ChainReproducesDiscrepancySeriesOfEq17)
  {
    const double R = 0.01, E = 1.85e6;
    for (const double nu : {0.1, 0.3, 0.46})
      for (const unsigned int N : {1u, 2u, 7u})
        {
          const double        q = (3 - 2 * nu) / (1 - nu);
          std::vector<double> eps, errors;
          for (double e = 1e-6; e <= 1.01e-3; e *= std::sqrt(10.0))
            {
              const double        Delta = 2.0 * N * R * e;
              const ChainSolution s
                = solve_chain_between_plates(N, Delta, R, E, nu);
              ASSERT_TRUE(s.converged);
              const double n_wall
                = 4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R);
              const double hertz = n_wall * std::pow(Delta / (2 * N), 1.5);
              EXPECT_NEAR(s.hertz_force, hertz, 1e-13 * hertz);
              const double D      = (s.force - hertz) / hertz;
              const double series = q / (2 * pi) * std::sqrt(e)
                                    + 7.0 / (24 * pi * pi) * q * q * e;
              eps.push_back(e);
              errors.push_back(D - series);
              const double c = q / (3 * pi);
              EXPECT_NEAR((D - series) / (5 * c * c * c * std::pow(e, 1.5)),
                          1.0,
                          0.05);
              // Geometry and equilibrium of the chain.
              EXPECT_NEAR(2 * s.wall_overlap + (N - 1.0) * s.sphere_overlap,
                          Delta,
                          1e-14 * Delta);
              const double n_s = hertz_coefficient(ElasticSphere{R, E, nu},
                                                   ElasticSphere{R, E, nu});
              EXPECT_NEAR(
                n_s
                  * std::pow(s.sphere_overlap + s.sphere_nonlocal_overlap, 1.5),
                s.force,
                1e-12 * s.force);
              EXPECT_NEAR(n_wall
                            * std::pow(s.wall_overlap + s.wall_nonlocal_overlap,
                                       1.5),
                          s.force,
                          1e-12 * s.force);
            }
          EXPECT_NEAR(log_log_slope(eps, errors), 1.5, 0.02);
        }
  }

  // The chain between plates as a general network: Algorithm 1 with the
  // chain's overlaps gives the chain's uniform force.
  TEST(NonlocalHertz, FixedPointReproducesChain)
  {
    const double        R = 0.01, E = 1.85e6, nu = 0.46;
    const unsigned int  N     = 5;
    const double        Delta = 2.0 * N * R * 0.01;
    const ChainSolution chain = solve_chain_between_plates(N, Delta, R, E, nu);
    ASSERT_TRUE(chain.converged);

    // Bodies 0..N-1 spheres along x, N and N+1 the plates.
    std::vector<NonlocalBody> bodies(N, NonlocalBody{R, E, nu});
    bodies.push_back({rigid, rigid, 0.0});
    bodies.push_back({rigid, rigid, 0.0});
    const ParticleLaw wall
      = hertz_law(hertz_coefficient({R, E, nu}, rigid_flat));
    const ParticleLaw pair
      = hertz_law(hertz_coefficient({R, E, nu}, {R, E, nu}));
    std::vector<NonlocalContactNetwork::Contact> contacts;
    std::vector<double>                          gamma;
    contacts.push_back({0, N, Eigen::Vector3d(-1, 0, 0), &wall});
    gamma.push_back(chain.wall_overlap);
    for (unsigned int i = 0; i + 1 < N; ++i)
      {
        contacts.push_back({i, i + 1, Eigen::Vector3d(1, 0, 0), &pair});
        gamma.push_back(chain.sphere_overlap);
      }
    contacts.push_back({N - 1, N + 1, Eigen::Vector3d(1, 0, 0), &wall});
    gamma.push_back(chain.wall_overlap);

    NonlocalContactNetwork network;
    network.build(bodies, contacts);
    EXPECT_EQ(network.n_incidences(), 2 * N);
    std::vector<double>            gamma_nl, force;
    const NonlocalFixedPointResult result
      = solve_nonlocal_fixed_point(network, gamma, gamma_nl, force, 1e-18, 200);
    ASSERT_TRUE(result.converged);
    for (std::size_t c = 0; c < force.size(); ++c)
      EXPECT_NEAR(force[c], chain.force, 1e-10 * chain.force);
    EXPECT_NEAR(gamma_nl.front(),
                chain.wall_nonlocal_overlap,
                1e-10 * chain.wall_nonlocal_overlap);
    EXPECT_NEAR(gamma_nl[1],
                chain.sphere_nonlocal_overlap,
                1e-10 * chain.sphere_nonlocal_overlap);
  }

  // A jammed 2-D cluster of two materials between two plates.
  struct Cluster
  {
    std::vector<NonlocalBody>                    bodies;
    std::vector<Eigen::Vector3d>                 x;
    std::vector<NonlocalContactNetwork::Contact> contacts;
    std::vector<double>                          gamma;
    // Hertz coefficient of each contact (Eq. 9) and the laws the contacts
    // point to (a deque: appending moves no law).
    std::vector<double>     n_H;
    std::deque<ParticleLaw> laws;

    void
    add(std::size_t            i,
        std::size_t            j,
        const Eigen::Vector3d &n,
        double                 g,
        double                 coefficient)
    {
      contacts.push_back({i, j, n, &laws.emplace_back(hertz_law(coefficient))});
      gamma.push_back(g);
      n_H.push_back(coefficient);
    }
  };

  Cluster
  make_cluster()
  {
    Cluster                                k;
    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> jitter(-1e-6, 1e-6);
    const double                           R = 100e-6, spacing = 1.97 * R;
    // Triangular lattice patch, 4 rows of 4.
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col)
        {
          const ElasticSphere &m = (row + col) % 2 ? sphere_a : sphere_b;
          k.bodies.push_back({R, m.E, m.nu});
          k.x.emplace_back(spacing * (col + 0.5 * (row % 2)) + jitter(rng),
                           spacing * std::sqrt(0.75) * row + jitter(rng),
                           jitter(rng));
        }
    const std::size_t n = k.bodies.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        {
          const Eigen::Vector3d d = k.x[j] - k.x[i];
          const double          g = 2 * R - d.norm();
          if (g > 0)
            {
              const ElasticSphere mi{R,
                                     k.bodies[i].youngs_modulus,
                                     k.bodies[i].poisson_ratio};
              const ElasticSphere mj{R,
                                     k.bodies[j].youngs_modulus,
                                     k.bodies[j].poisson_ratio};
              k.add(i, j, d.normalized(), g, hertz_coefficient(mi, mj));
            }
        }
    // Plates below the first row and above the last one.
    const double bottom = -R + 2e-6,
                 top    = spacing * std::sqrt(0.75) * 3 + R - 2e-6;
    k.bodies.push_back({rigid, rigid, 0.0});
    k.bodies.push_back({rigid, rigid, 0.0});
    for (std::size_t i = 0; i < n; ++i)
      {
        const ElasticSphere mi{R,
                               k.bodies[i].youngs_modulus,
                               k.bodies[i].poisson_ratio};
        if (k.x[i].y() - R < bottom)
          {
            k.add(i,
                  n,
                  Eigen::Vector3d(0, -1, 0),
                  bottom - (k.x[i].y() - R),
                  hertz_coefficient(mi, rigid_flat));
          }
        if (k.x[i].y() + R > top)
          {
            k.add(i,
                  n + 1,
                  Eigen::Vector3d(0, 1, 0),
                  k.x[i].y() + R - top,
                  hertz_coefficient(mi, rigid_flat));
          }
      }
    return k;
  }

  TEST(NonlocalHertz, FixedPointConvergesToIndependentResidual)
  {
    const Cluster k = make_cluster();
    ASSERT_GT(k.contacts.size(), 30u);
    NonlocalContactNetwork network;
    network.build(k.bodies, k.contacts);
    std::vector<double>            gamma_nl, force;
    const NonlocalFixedPointResult result = solve_nonlocal_fixed_point(
      network, k.gamma, gamma_nl, force, 1e-20, 200);
    ASSERT_TRUE(result.converged);
    EXPECT_GT(result.iterations, 2u);
    EXPECT_LT(result.change, 1e-20);

    // Residual of Eqs. (5), (9), (10) evaluated here, pair by pair.
    double largest_shift = 0;
    for (std::size_t c = 0; c < k.contacts.size(); ++c)
      {
        const auto &cc   = k.contacts[c];
        double      g_nl = 0;
        for (std::size_t d = 0; d < k.contacts.size(); ++d)
          {
            if (d == c)
              continue;
            const auto &cd = k.contacts[d];
            for (const std::size_t p : {cc.particle_i, cc.particle_j})
              {
                if (cd.particle_i != p && cd.particle_j != p)
                  continue;
                const NonlocalBody   &b     = k.bodies[p];
                const Eigen::Vector3d u     = cc.particle_i == p
                                                ? cc.normal
                                                : Eigen::Vector3d(-cc.normal);
                const Eigen::Vector3d v     = cd.particle_i == p
                                                ? cd.normal
                                                : Eigen::Vector3d(-cd.normal);
                const double          theta = std::acos(u.dot(v));
                g_nl += eq5(force[d],
                            theta,
                            {b.radius, b.youngs_modulus, b.poisson_ratio});
              }
          }
        EXPECT_NEAR(gamma_nl[c], g_nl, 1e-12 * k.gamma[c]);
        EXPECT_NEAR(force[c],
                    k.n_H[c] * std::pow(std::max(k.gamma[c] + g_nl, 0.0), 1.5),
                    1e-10 * force[c] + 1e-30);
        largest_shift = std::max(largest_shift, std::abs(g_nl) / k.gamma[c]);
      }
    // The nonlocal terms matter in this packing.
    EXPECT_GT(largest_shift, 1e-3);
  }

  TEST(NonlocalHertz, FixedPointIndependentOfContactOrdering)
  {
    const Cluster          k = make_cluster();
    NonlocalContactNetwork network;
    network.build(k.bodies, k.contacts);
    std::vector<double> gamma_nl, force;
    ASSERT_TRUE(
      solve_nonlocal_fixed_point(network, k.gamma, gamma_nl, force, 1e-20, 200)
        .converged);

    // Shuffle the contacts and swap the roles of i and j in every other one.
    std::vector<std::size_t> order(k.contacts.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(11));
    std::vector<NonlocalContactNetwork::Contact> shuffled;
    std::vector<double>                          gamma;
    for (std::size_t q = 0; q < order.size(); ++q)
      {
        NonlocalContactNetwork::Contact c = k.contacts[order[q]];
        if (q % 2)
          {
            std::swap(c.particle_i, c.particle_j);
            c.normal = -c.normal;
          }
        shuffled.push_back(c);
        gamma.push_back(k.gamma[order[q]]);
      }
    NonlocalContactNetwork other;
    other.build(k.bodies, shuffled);
    std::vector<double> gamma_nl2, force2;
    ASSERT_TRUE(
      solve_nonlocal_fixed_point(other, gamma, gamma_nl2, force2, 1e-20, 200)
        .converged);
    for (std::size_t q = 0; q < order.size(); ++q)
      {
        EXPECT_NEAR(force2[q], force[order[q]], 1e-12 * force[order[q]]);
        EXPECT_NEAR(gamma_nl2[q],
                    gamma_nl[order[q]],
                    1e-12 * k.gamma[order[q]]);
      }

    // Streaming construction of the same network gives the same result,
    // and a warm start from the converged state stops after one sweep.
    NonlocalContactNetwork streamed;
    streamed.reserve(k.contacts.size(), network.n_incidences());
    for (std::size_t c = 0; c < k.contacts.size(); ++c)
      {
        streamed.add_contact(*k.contacts[c].law);
        for (std::size_t q = network.offset()[c]; q < network.offset()[c + 1];
             ++q)
          streamed.add_influence(network.other()[q], network.compliance()[q]);
      }
    std::vector<double>            gamma_nl3 = gamma_nl, force3;
    const NonlocalFixedPointResult warm      = solve_nonlocal_fixed_point(
      streamed, k.gamma, gamma_nl3, force3, 1e-20, 200, true);
    EXPECT_TRUE(warm.converged);
    EXPECT_LE(warm.iterations, 2u);
    for (std::size_t c = 0; c < force.size(); ++c)
      EXPECT_NEAR(force3[c], force[c], 1e-13 * force[c]);
  }
} // namespace

TEST(NonlocalFixedPoint, DivergenceBeyondTheLimitPointIsNotConvergence)
{
  // Two contacts that load each other (one particle between them): with
  // w n_H large and a large overlap the fixed point of Eq. (10) has no
  // solution and the iteration runs off to infinity; it must say so.
  const ParticleLaw      unit = hertz_law(1.0);
  NonlocalContactNetwork network;
  network.add_contact(unit);
  network.add_influence(1, 1.0);
  network.add_contact(unit);
  network.add_influence(0, 1.0);
  std::vector<double> gamma{1.0, 1.0}, gamma_nl, force;
  const auto          result
    = solve_nonlocal_fixed_point(network, gamma, gamma_nl, force, 1e-12, 200);
  EXPECT_FALSE(result.converged);

  // Below the limit point the same network converges.
  std::vector<double> small{1e-4, 1e-4};
  EXPECT_TRUE(
    solve_nonlocal_fixed_point(network, small, gamma_nl, force, 1e-16, 200)
      .converged);
}

// The trust-region solver of the nonlocal formulation: its model Hessian
// (the frozen-angle Jacobian) checked for the symmetry that makes it a
// Hessian and against the exact Jacobian where the two must agree (Hertz);
// the solver checked against the closed form of the chain between plates
// (Eqs. 11, 17, solved here by bisection) and by Newton's third law on the
// walls of a compacted bed; Hertz consolidation checked to run no
// Algorithm 1 sweep before jamming.

#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/nonlocal/nonlocal_trust_region.h"
#include "dem/nonlocal/square_die_compaction.h"
#include "dem/nonlocal/square_die_deposition.h"
#include "dem/solver/trust_region_newton.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
  using namespace compax::dem;

  constexpr double pi = 3.14159265358979323846;

  const std::vector<ElasticMaterial> two_materials{{19e9, 0.30}, {7e9, 0.20}};

  struct Cluster
  {
    ParticleSystem particles;
    SquareDie      die;
  };

  /// 2x2x2 spheres on a perturbed cubic lattice pressed by ~2 % of R
  /// together and against the six walls.
  Cluster
  make_cluster(const unsigned int seed)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Cluster                                c;
    const double                           R = 100e-6, a = 1.96 * R;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          {
            const Eigen::Vector3d x((i - 0.5) * a + 3e-3 * R * u(gen),
                                    (j - 0.5) * a + 3e-3 * R * u(gen),
                                    (k + 0.5) * a + 3e-3 * R * u(gen));
            c.particles.add(x, R * (1.0 + 0.01 * u(gen)), (i + j + k) % 2);
          }
    c.die.width              = 2.0 * a;
    c.die.lower_punch_height = 0.0;
    c.die.upper_punch_height = 2.0 * a;
    return c;
  }

  Eigen::VectorXd
  random_vector(std::mt19937 &gen, const Eigen::Index n)
  {
    std::normal_distribution<double> normal;
    Eigen::VectorXd                  v(n);
    for (Eigen::Index k = 0; k < n; ++k)
      v[k] = normal(gen);
    return v;
  }

  TEST(NonlocalTrustRegion, FrozenAngleJacobianIsSymmetric)
  {
    for (unsigned int seed : {1u, 2u, 5u, 7u})
      {
        Cluster            c = make_cluster(seed);
        NonlocalBedOptions o;
        o.fixed_point_tolerance      = 1e-15;
        o.max_fixed_point_iterations = 100000;
        NonlocalBedSystem system(c.particles, two_materials, c.die, o);
        Eigen::VectorXd   F, Hu, Hv, Ju;
        system.residual(F);
        ASSERT_TRUE(F.allFinite());
        std::mt19937          gen(seed);
        const Eigen::VectorXd u = random_vector(gen, F.size());
        const Eigen::VectorXd v = random_vector(gen, F.size());
        system.apply_jacobian(u, Hu, false);
        system.apply_jacobian(v, Hv, false);
        const double scale = Hu.norm() * v.norm();
        // v.H u = u.H v: (D^-1 - C)^-1 is symmetric because C is.
        EXPECT_LE(std::abs(v.dot(Hu) - u.dot(Hv)), 1e-10 * scale)
          << "seed " << seed;
        // The turning terms are what makes the full Jacobian nonsymmetric,
        // and they are not negligible at this compression.
        system.apply_jacobian(u, Ju, true);
        EXPECT_GT((Ju - Hu).norm(), 1e-6 * Ju.norm()) << "seed " << seed;
      }
  }

  TEST(NonlocalTrustRegion, FrozenAngleJacobianIsExactForHertz)
  {
    // Without the nonlocal terms there is no influence coefficient to turn:
    // both products are the Hertz Jacobian.
    for (unsigned int seed : {1u, 3u})
      {
        Cluster            c = make_cluster(seed);
        NonlocalBedOptions o;
        o.nonlocal = false;
        NonlocalBedSystem system(c.particles, two_materials, c.die, o);
        Eigen::VectorXd   F, H, J;
        system.residual(F);
        std::mt19937          gen(seed);
        const Eigen::VectorXd v = random_vector(gen, F.size());
        system.apply_jacobian(v, H, false);
        system.apply_jacobian(v, J, true);
        EXPECT_LE((H - J).norm(), 1e-14 * J.norm());
      }
  }

  /// Chain of n spheres between the punches, approach Delta, the inner
  /// spheres displaced from equilibrium.
  Cluster
  make_chain(unsigned int n, double R, double Delta)
  {
    Cluster      c;
    const double H           = 2.0 * n * R - Delta;
    c.die.width              = 10.0 * R;
    c.die.upper_punch_height = H;
    for (unsigned int k = 0; k < n; ++k)
      {
        double z = (k + 0.5) * H / n;
        if (k > 0 && k + 1 < n)
          z += 0.2 * Delta / n * (k % 2 ? 1.0 : -1.0);
        c.particles.add(Eigen::Vector3d(0, 0, z), R, 0);
      }
    return c;
  }

  /// P = n_w (Delta / 2N + c P)^{3/2} (Eqs. 10, 11), lower root by
  /// bisection.
  double
  chain_force(unsigned int n, double R, double E, double nu, double Delta)
  {
    const double n_w = 4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R);
    const double c   = (1 + nu) * (3 - 2 * nu) / (4 * pi * R * E);
    const double g   = Delta / (2.0 * n);
    double       lo = n_w * std::pow(g, 1.5), hi = lo;
    while (hi - n_w * std::pow(g + c * hi, 1.5) < 0)
      hi *= 1.01;
    for (int i = 0; i < 200; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (mid - n_w * std::pow(g + c * mid, 1.5) < 0 ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }

  TEST(NonlocalTrustRegion, ReachesChainClosedForm)
  {
    const double                       R = 0.01, E = 1.85e6, nu = 0.46;
    const std::vector<ElasticMaterial> rubber{{E, nu}};
    for (const unsigned int n : {1u, 3u, 5u})
      for (const double eps : {0.002, 0.02})
        for (const double krylov_switch : {0.0, 1e-2})
          {
            const double               Delta = 2.0 * n * R * eps;
            Cluster                    c     = make_chain(n, R, Delta);
            NonlocalBedSystem          system(c.particles, rubber, c.die);
            NonlocalTrustRegionOptions o;
            o.krylov_switch = krylov_switch;
            const NonlocalTrustRegionResult r
              = NonlocalTrustRegion(o).solve(system);
            ASSERT_TRUE(r.converged) << n << ' ' << eps;
            if (krylov_switch == 0.0)
              {
                EXPECT_EQ(r.krylov_iterations, 0);
              }
            Eigen::VectorXd F;
            system.residual(F);
            const double P = chain_force(n, R, E, nu, Delta);
            EXPECT_NEAR(system.wall_forces()[SquareDie::upper_punch],
                        P,
                        1e-6 * P);
            EXPECT_NEAR(system.wall_forces()[SquareDie::lower_punch],
                        P,
                        1e-6 * P);
          }
  }

  TEST(NonlocalTrustRegion, ClusterReachesEquilibrium)
  {
    for (unsigned int seed : {1u, 2u, 5u})
      {
        Cluster                    c = make_cluster(seed);
        NonlocalBedSystem          system(c.particles, two_materials, c.die);
        NonlocalTrustRegionOptions o;
        o.krylov_switch = 0.0; // the trust region alone
        const NonlocalTrustRegionResult r
          = NonlocalTrustRegion(o).solve(system);
        ASSERT_TRUE(r.converged) << seed;
        Eigen::VectorXd   F;
        const ContactSums sums = system.residual(F);
        EXPECT_LE(max_particle_norm(F), 1e-6 * sums.mean_force);
        const auto  &w   = system.wall_forces();
        const double tol = 1e-5 * w[SquareDie::upper_punch];
        EXPECT_NEAR(w[SquareDie::lower_punch], w[SquareDie::upper_punch], tol);
        EXPECT_NEAR(w[SquareDie::x_lower], w[SquareDie::x_upper], tol);
        EXPECT_NEAR(w[SquareDie::y_lower], w[SquareDie::y_upper], tol);
      }
  }

  TEST(NonlocalTrustRegion, HertzConsolidationRunsNoFixedPoint)
  {
    SquareDepositionParameters dp;
    dp.width = 1e-3;
    dp.sizes
      = {{77.46e-6, 0.0161, 75e-6, 80e-6}, {144.5e-6, 0.0724, 125e-6, 167e-6}};
    dp.counts                = {40, 6};
    dp.seed                  = 4;
    const ParticleSystem p   = square_die_deposition(dp);
    double               top = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      top = std::max(top, p.positions[i][2] + p.radii[i]);
    SquareDie die;
    die.width              = 1e-3;
    die.upper_punch_height = top;
    for (const bool hertz_consolidation : {true, false})
      {
        BedCompactionOptions o;
        o.final_density       = 0.62;
        o.density_step        = 0.01;
        o.jamming_pressure    = 2e5;
        o.hertz_consolidation = hertz_consolidation;
        const BedCompactionResult r
          = compact_square_die_bed(p, two_materials, die, true, o);
        ASSERT_TRUE(r.complete) << r.stop_reason;
        std::size_t unjammed_sweeps = 0, jammed_sweeps = 0;
        for (const auto &pt : r.points)
          (pt.jammed ? jammed_sweeps : unjammed_sweeps) += pt.sweeps;
        ASSERT_TRUE(r.points.back().jammed);
        EXPECT_GT(jammed_sweeps, 0u);
        if (hertz_consolidation)
          EXPECT_EQ(unjammed_sweeps, 0u);
        else
          EXPECT_GT(unjammed_sweeps, 0u);
        // Equilibrium of the nonlocal bed at the end: opposite walls carry
        // the same force (no gravity).
        const auto  &w   = r.points.back().wall_force;
        const double tol = 1e-4 * w[SquareDie::upper_punch];
        EXPECT_NEAR(w[SquareDie::lower_punch], w[SquareDie::upper_punch], tol);
        EXPECT_NEAR(w[SquareDie::x_lower], w[SquareDie::x_upper], tol);
        EXPECT_NEAR(w[SquareDie::y_lower], w[SquareDie::y_upper], tol);
        EXPECT_GT(r.points.back().nonlocal_ratio, 0.0);
      }
  }
} // namespace

namespace
{
  using namespace compax::dem;

  TEST(NonlocalTrustRegion, SmallBedCompactsToHighDensity)
  {
    // A small bed compacted to a high density with the default solver:
    // every step converges and ends in equilibrium (opposite walls carry
    // the same force), and the nonlocal bed carries more load than the
    // Hertz bed (the nonlocal terms of the opposite contacts add overlap).
    SquareDepositionParameters dp;
    dp.width = 0.8e-3;
    dp.sizes
      = {{77.46e-6, 0.0161, 75e-6, 80e-6}, {144.5e-6, 0.0724, 125e-6, 167e-6}};
    dp.counts                = {50, 7};
    dp.seed                  = 2;
    const ParticleSystem p   = square_die_deposition(dp);
    double               top = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      top = std::max(top, p.positions[i][2] + p.radii[i]);
    SquareDie die;
    die.width              = dp.width;
    die.upper_punch_height = top;
    BedCompactionOptions o;
    o.final_density    = 0.75;
    o.density_step     = 0.01;
    o.jamming_pressure = 2e5;
    double load[2];
    for (const bool nonlocal : {false, true})
      {
        const BedCompactionResult r
          = compact_square_die_bed(p, two_materials, die, nonlocal, o);
        ASSERT_TRUE(r.complete) << r.stop_reason;
        const auto &last = r.points.back();
        EXPECT_NEAR(last.relative_density, 0.75, 1e-9);
        for (const auto &pt : r.points)
          EXPECT_TRUE(pt.converged);
        const auto  &w   = last.wall_force;
        const double tol = 1e-4 * w[SquareDie::upper_punch];
        EXPECT_NEAR(w[SquareDie::lower_punch], w[SquareDie::upper_punch], tol);
        EXPECT_NEAR(w[SquareDie::x_lower], w[SquareDie::x_upper], tol);
        EXPECT_NEAR(w[SquareDie::y_lower], w[SquareDie::y_upper], tol);
        load[nonlocal] = w[SquareDie::upper_punch];
      }
    EXPECT_GT(load[1], load[0]);
  }
} // namespace

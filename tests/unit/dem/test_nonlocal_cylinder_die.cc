// The nonlocal contact formulation (Gonzalez & Cuitino 2012) in the
// cylindrical die of `compax die`: the exact Jacobian with the turning
// normal of the curved die wall against central finite differences of the
// residual, a chain of spheres across the die against the closed form of
// Eqs. (10), (11) (solved here by bisection), and the die protocol with
// elastic spheres: every converged state within its residual of the
// punch-force balance.

#include "dem/die/die_compaction.h"
#include "dem/die/die_setup.h"
#include "dem/nonlocal/elastic_die_stepper.h"
#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/solver/trust_region_newton.h"
#include "tests/support/gonzalez_material1.h"

#include "nonlocal_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <vector>

namespace
{
  using namespace compax::dem;
  using namespace compax::dem::nonlocal_test;

  struct CylinderCluster
  {
    ParticleSystem particles;
    DieWalls       die;
  };

  /// A ring of six spheres pressed against the curved die wall (overlap
  /// ~1.5 % of R) and against a centre sphere and each other (~2 %), all
  /// between the two punches (~1 %), with random perturbations (radii
  /// 0.3 %, centres 0.3 %, the centre sphere 0.7 % off the axis: every
  /// contact stays closed).
  CylinderCluster
  make_ring(const unsigned int seed)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    CylinderCluster                        c;
    const double                           R = 100e-6, r0 = 1.98 * R;
    const auto                             jitter = [&]() -> Eigen::Vector3d {
      // The return type evaluates the product (an Eigen expression
      // returned by value would refer to the destroyed temporary).
      return Eigen::Vector3d(u(gen), u(gen), u(gen)) * 3e-3 * R;
    };
    c.particles.add(Eigen::Vector3d(0.005 * R, -0.005 * R, 0) + jitter(),
                    R * (1.0 + 0.003 * u(gen)),
                    0);
    for (int k = 0; k < 6; ++k)
      {
        const double t = k * pi / 3.0 + 0.1;
        c.particles.add(Eigen::Vector3d(r0 * std::cos(t), r0 * std::sin(t), 0)
                          + jitter(),
                        R * (1.0 + 0.003 * u(gen)),
                        k % 2);
      }
    c.die.diameter    = 2.0 * 2.965 * R;
    c.die.lower_punch = -0.99 * R;
    c.die.upper_punch = 0.99 * R;
    return c;
  }

  TEST(NonlocalCylinderDie, JacobianWithCurvedWallIsCentralDifference)
  {
    for (const bool nonlocal : {false, true})
      for (unsigned int seed : {1u, 4u})
        {
          CylinderCluster   c = make_ring(seed);
          NonlocalBedSystem system(c.particles,
                                   two_materials,
                                   c.die,
                                   converged_fixed_point(1e-16, nonlocal));
          Eigen::VectorXd   F;
          BlockSparseMatrix K;
          system.assemble(F, K);
          ASSERT_TRUE(F.allFinite())
            << "nonlocal " << nonlocal << " seed " << seed << " sweeps "
            << system.fixed_point().iterations;
          // The ring is pressed against the curved wall, all six spheres.
          ASSERT_GT(system.wall_forces()[int(Wall::die)], 0.0);
          ASSERT_GE(system.n_loaded(), 6u + 6u + 6u + 2u * 7u);
          // Hertz: the assembled K (local stiffness, pair and curved-wall
          // geometric terms) is the exact Jacobian.
          expect_jacobian_is_central_difference(system, K, seed, 1e-8 * 100e-6);
        }
  }

  TEST(NonlocalCylinderDie, ChainAcrossTheDieReachesClosedForm)
  {
    // N spheres on a diameter of the die, squeezed by the curved wall
    // (die diameter 2NR - Delta), punches far away; the middle spheres
    // start off their equilibrium. The wall law is that of a flat (the
    // die's curvature is neglected in it, as for the bonded law).
    const double                       R = 0.01, E = 1.85e6, nu = 0.46;
    const std::vector<ElasticMaterial> rubber{{E, nu}};
    for (const unsigned int n : {2u, 3u})
      for (const double eps : {0.002, 0.02})
        for (const bool nonlocal : {false, true})
          {
            const double   Delta = 2.0 * n * R * eps;
            ParticleSystem p;
            DieWalls       die;
            die.diameter    = 2.0 * n * R - Delta;
            die.lower_punch = -5 * R;
            die.upper_punch = 5 * R;
            for (unsigned int k = 0; k < n; ++k)
              {
                double x = (k + 0.5 - 0.5 * n) * die.diameter / n;
                if (k > 0 && k + 1 < n)
                  x += 0.2 * Delta / n;
                p.add(Eigen::Vector3d(x, 0, 0), R, 0);
              }
            NonlocalBedOptions o;
            o.nonlocal = nonlocal;
            NonlocalBedSystem       system(p, rubber, die, o);
            TrustRegionNewton       solver(nonlocal_equilibrium_options());
            const EquilibriumResult r = solver.solve(system);
            ASSERT_TRUE(r.converged) << n << ' ' << eps << ' ' << nonlocal;
            Eigen::VectorXd F;
            system.residual(F);
            const double P = nonlocal
                               ? chain_force(n, R, E, nu, Delta)
                               : 4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R)
                                   * std::pow(Delta / (2.0 * n), 1.5);
            // Two wall contacts, one at each end of the chain.
            EXPECT_NEAR(system.wall_forces()[int(Wall::die)], 2 * P, 2e-6 * P)
              << n << ' ' << eps << ' ' << nonlocal;
            EXPECT_EQ(system.wall_forces()[int(Wall::upper_punch)], 0.0);
            EXPECT_EQ(system.n_loaded(), n + 1);
          }
  }

  TEST(NonlocalCylinderDie, ElasticDieProtocolBalancesPunchForces)
  {
    DepositionParameters dp;
    dp.n_particles         = 40;
    dp.die_diameter        = 1e-3;
    dp.sizes.median_radius = 100e-6;
    dp.seed                = 2;
    const Bed bed          = fill_die(dp);
    for (const bool nonlocal : {false, true})
      {
        DieProtocol protocol;
        protocol.compaction_targets
          = density_targets(bed.relative_density(), 0.62, 5);
        protocol.unloading_points = {0.62};
        ElasticDieOptions elastic;
        elastic.materials = {{10e9, 0.3}};
        elastic.nonlocal  = nonlocal;
        protocol.elastic  = elastic;
        // The bonded law is not used with elastic spheres.
        const ContactModel model = compax::testing::material1::contact_model();
        DieCompaction      die(bed, model, protocol);
        std::ostringstream csv;
        die.set_output(&csv, nullptr);
        ASSERT_NO_THROW(die.run()) << nonlocal;
        ASSERT_GT(die.jamming_density(), 0.0);
        const double tol     = nonlocal_equilibrium_options().force_tolerance;
        bool         reached = false, unloaded = false;
        for (const DieRecord &r : die.records())
          {
            if (r.stage == "compaction" && r.step == 0)
              continue; // the deposit as filled (no equilibrium solve)
            // Sum over particles of F_z = P_upper - P_lower, and
            // |sum F_i| <= N max |F_i| = N residual mean |P|.
            EXPECT_LE(r.residual, tol) << r.stage << ' ' << r.step;
            EXPECT_LE(std::abs(r.upper_punch_force - r.lower_punch_force),
                      40 * r.residual * r.mean_contact_force
                        + 1e-12 * r.upper_punch_force)
              << r.stage << ' ' << r.step;
            EXPECT_EQ(r.bonds, 0u);
            reached |= r.stage == "compaction"
                       && std::abs(r.relative_density - 0.62) < 1e-12
                       && r.upper_punch_force > 0.0;
            unloaded |= r.stage == "unloading"
                        && r.upper_punch_force <= die.force_resolution();
          }
        EXPECT_TRUE(reached) << nonlocal;
        EXPECT_TRUE(unloaded) << nonlocal;
        ASSERT_EQ(die.branches().size(), 1u);
        EXPECT_LT(die.branches()[0].rho_min_in_die, 0.62);
      }
  }
} // namespace

// The trust-region solver of the nonlocal formulation: its model Hessian
// (the frozen-angle Jacobian) checked for the symmetry that makes it a
// Hessian and against the exact Jacobian where the two must agree (Hertz);
// the solver checked against the closed form of the chain between plates
// (Eqs. 11, 17, solved here by bisection) and by Newton's third law on the
// walls of a compacted bed; Hertz consolidation checked to run no
// Algorithm 1 sweep before jamming.

#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/nonlocal/square_die_compaction.h"
#include "dem/nonlocal/square_die_deposition.h"
#include "dem/solver/trust_region_newton.h"

#include "nonlocal_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
  using namespace compax::dem;
  using namespace compax::dem::nonlocal_test;

  TEST(NonlocalTrustRegion, FrozenAngleJacobianIsSymmetric)
  {
    for (unsigned int seed : {1u, 2u, 5u, 7u})
      {
        Cluster                  c = make_cluster(seed);
        const NonlocalBedOptions o = converged_fixed_point(1e-15);
        NonlocalBedSystem        system(c.particles, two_materials, c.die, o);
        Eigen::VectorXd          F, Hu, Hv, Ju;
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

  TEST(NonlocalTrustRegion, ReachesChainClosedForm)
  {
    const double                       R = 0.01, E = 1.85e6, nu = 0.46;
    const std::vector<ElasticMaterial> rubber{{E, nu}};
    for (const unsigned int n : {1u, 3u, 5u})
      for (const double eps : {0.002, 0.02})
        for (const double krylov_switch : {0.0, 1e-2})
          {
            const double       Delta = 2.0 * n * R * eps;
            Cluster            c     = make_chain(n, R, Delta);
            NonlocalBedSystem  system(c.particles, rubber, c.die);
            EquilibriumOptions o      = nonlocal_equilibrium_options();
            o.krylov_switch           = krylov_switch;
            const EquilibriumResult r = TrustRegionNewton(o).solve(system);
            ASSERT_TRUE(r.converged) << n << ' ' << eps;
            if (krylov_switch == 0.0)
              {
                EXPECT_EQ(r.krylov_iterations, 0);
              }
            const double P = chain_force(n, R, E, nu, Delta);
            expect_punch_forces(system, P, 1e-6);
          }
  }

  TEST(NonlocalTrustRegion, ClusterReachesEquilibrium)
  {
    for (unsigned int seed : {1u, 2u, 5u})
      {
        Cluster            c = make_cluster(seed);
        NonlocalBedSystem  system(c.particles, two_materials, c.die);
        EquilibriumOptions o      = nonlocal_equilibrium_options();
        o.krylov_switch           = 0.0; // the trust region alone
        const EquilibriumResult r = TrustRegionNewton(o).solve(system);
        ASSERT_TRUE(r.converged) << seed;
        Eigen::VectorXd   F;
        const ContactSums sums = system.residual(F);
        EXPECT_LE(max_particle_norm(F), 1e-6 * sums.mean_force);
        const auto  &w   = system.wall_forces();
        const double tol = 1e-5 * w[SquareDie::upper_punch];
        expect_opposite_walls_balance(w, tol);
      }
  }

  TEST(NonlocalTrustRegion, HertzConsolidationRunsNoFixedPoint)
  {
    const Cluster bed = deposited_square_die_bed(1e-3, {40, 6}, 4);
    for (const bool hertz_consolidation : {true, false})
      {
        BedCompactionOptions o;
        o.final_density             = 0.62;
        o.density_step              = 0.01;
        o.jamming_pressure          = 2e5;
        o.hertz_consolidation       = hertz_consolidation;
        const BedCompactionResult r = compact_square_die_bed(
          bed.particles, two_materials, bed.die, true, o);
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
        expect_opposite_walls_balance(w, tol);
        EXPECT_GT(r.points.back().nonlocal_ratio, 0.0);
      }
  }

  TEST(NonlocalTrustRegion, SmallBedCompactsToHighDensity)
  {
    // A small bed compacted to a high density with the default solver:
    // every step converges and ends in equilibrium (opposite walls carry
    // the same force), and the nonlocal bed carries more load than the
    // Hertz bed (the nonlocal terms of the opposite contacts add overlap).
    const Cluster        bed = deposited_square_die_bed(0.8e-3, {50, 7}, 2);
    BedCompactionOptions o;
    o.final_density    = 0.75;
    o.density_step     = 0.01;
    o.jamming_pressure = 2e5;
    double load[2];
    for (const bool nonlocal : {false, true})
      {
        const BedCompactionResult r = compact_square_die_bed(
          bed.particles, two_materials, bed.die, nonlocal, o);
        ASSERT_TRUE(r.complete) << r.stop_reason;
        const auto &last = r.points.back();
        EXPECT_NEAR(last.relative_density, 0.75, 1e-9);
        for (const auto &pt : r.points)
          EXPECT_TRUE(pt.converged);
        const auto  &w   = last.wall_force;
        const double tol = 1e-4 * w[SquareDie::upper_punch];
        expect_opposite_walls_balance(w, tol);
        load[nonlocal] = w[SquareDie::upper_punch];
      }
    EXPECT_GT(load[1], load[0]);
  }
} // namespace

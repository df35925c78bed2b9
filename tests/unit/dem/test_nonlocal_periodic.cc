// The nonlocal contact formulation (Gonzalez & Cuitino 2012) in a periodic
// cell: the simple cubic crystal under hydrostatic compression against the
// closed form of Eqs. (5), (9), (10) (influence coefficients written out
// here from Eq. 5, force solved by bisection) and its Love-Weber stress,
// and the exact Jacobian in a sheared cell with contacts through lattice
// images against central finite differences of the residual.

#include "dem/nonlocal/nonlocal_bed_system.h"

#include "nonlocal_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
  using namespace compax::dem;
  using namespace compax::dem::nonlocal_test;

  /// 2 x 2 x 2 simple cubic spheres of radius R at spacing a in a cubic
  /// periodic cell of side 2a (every particle touches two others through
  /// lattice images), with an optional random perturbation and shear.
  struct Crystal
  {
    ParticleSystem particles;
    PeriodicCell   cell
      = PeriodicCell::box(Eigen::Vector3d::Ones(), {true, true, true});
  };

  Crystal
  simple_cubic(const double       R,
               const double       a,
               const double       perturbation = 0.0,
               const double       shear        = 0.0,
               const unsigned int seed         = 1)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Crystal                                c;
    Eigen::Matrix3d H = 2.0 * a * Eigen::Matrix3d::Identity();
    H(0, 1)           = shear * 2.0 * a;
    c.cell.set_lattice(H);
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          {
            const Eigen::Vector3d s(0.25 + 0.5 * i,
                                    0.25 + 0.5 * j,
                                    0.25 + 0.5 * k);
            const Eigen::Vector3d jitter(u(gen), u(gen), u(gen));
            c.particles.add(
              H * s + perturbation * R * jitter,
              R * (1.0 + (perturbation > 0 ? 0.01 * u(gen) : 0.0)),
              (i + j + k) % 2);
          }
    return c;
  }

  TEST(NonlocalPeriodic, SimpleCubicHydrostaticIsClosedForm)
  {
    const double R = 0.01;
    for (const double nu : {0.46, 0.3})
      for (const double eps : {0.002, 0.02})
        for (const bool nonlocal : {false, true})
          {
            const double                       E = 1.85e6;
            const std::vector<ElasticMaterial> rubber{{E, nu}, {E, nu}};
            const double                       a = 2 * R * (1 - eps);
            Crystal                            c = simple_cubic(R, a);
            NonlocalBedOptions                 o;
            o.nonlocal = nonlocal;
            NonlocalBedSystem system(c.particles, rubber, c.cell, o);
            Eigen::VectorXd   F;
            system.residual(F);
            ASSERT_TRUE(F.allFinite());
            // Six contacts per sphere, each shared by two.
            EXPECT_EQ(system.n_loaded(), 24u);
            const double P = simple_cubic_force(R, E, nu, a, nonlocal);
            // The perfect lattice is in equilibrium.
            EXPECT_LE(F.cwiseAbs().maxCoeff(), 1e-9 * P);
            // sigma = -(1/V) sum P a e e^T: 8 contacts along each axis in
            // the cell of volume 8 a^3.
            const Eigen::Matrix3d S = system.stress();
            for (int r = 0; r < 3; ++r)
              for (int s = 0; s < 3; ++s)
                EXPECT_NEAR(S(r, s),
                            r == s ? -P / (a * a) : 0.0,
                            1e-8 * P / (a * a))
                  << nu << ' ' << eps << ' ' << nonlocal << ' ' << r << s;
          }
  }

  TEST(NonlocalPeriodic, JacobianInShearedCellIsCentralDifference)
  {
    const double R = 100e-6;
    for (const bool nonlocal : {false, true})
      for (unsigned int seed : {2u, 3u})
        {
          Crystal           c = simple_cubic(R, 1.97 * R, 3e-3, 0.01, seed);
          NonlocalBedSystem system(c.particles,
                                   two_materials,
                                   c.cell,
                                   converged_fixed_point(1e-16, nonlocal));
          Eigen::VectorXd   F;
          BlockSparseMatrix K;
          system.assemble(F, K);
          ASSERT_TRUE(F.allFinite());
          ASSERT_GE(system.n_loaded(), 20u);
          expect_jacobian_is_central_difference(system, K, seed, 1e-8 * R);
        }
  }
} // namespace

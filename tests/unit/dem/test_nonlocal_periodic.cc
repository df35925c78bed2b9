// The nonlocal contact formulation (Gonzalez & Cuitino 2012) in a periodic
// cell: the simple cubic crystal under hydrostatic compression against the
// closed form of Eqs. (5), (9), (10) (influence coefficients written out
// here from Eq. 5, force solved by bisection) and its Love-Weber stress,
// and the exact Jacobian in a sheared cell with contacts through lattice
// images against central finite differences of the residual.

#include "dem/nonlocal/nonlocal_bed_system.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
  using namespace compax::dem;

  constexpr double pi = 3.14159265358979323846;

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

  /// Eq. (5) per unit force: the displacement of a contact point of a
  /// sphere (R, E, nu) by a unit force at angle theta from it.
  double
  influence(const double R, const double E, const double nu, const double theta)
  {
    const double h = std::sin(theta / 2);
    return (1 + nu) / (4 * pi * R * E)
           * (-2 * (1 - nu) - 2 * (1 - 2 * nu) * h + (7 - 8 * nu) * h * h) / h;
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
            // Equal spheres: n_H = 4/3 E* sqrt(R*), E* = E / 2(1 - nu^2),
            // R* = R / 2. On each sphere a contact sees the opposite one
            // (theta = pi) and four at theta = pi / 2; both spheres add.
            const double n_H
              = 4.0 / 3.0 * E / (2 * (1 - nu * nu)) * std::sqrt(R / 2);
            const double gamma = 2 * R - a;
            const double k     = nonlocal ? 2
                                          * (influence(R, E, nu, pi)
                                             + 4 * influence(R, E, nu, pi / 2))
                                          : 0.0;
            double       lo = n_H * std::pow(gamma, 1.5), hi = lo;
            while (hi - n_H * std::pow(gamma + k * hi, 1.5) < 0)
              hi *= 1.01;
            for (int i = 0; i < 200; ++i)
              {
                const double mid = 0.5 * (lo + hi);
                (mid - n_H * std::pow(gamma + k * mid, 1.5) < 0 ? lo : hi)
                  = mid;
              }
            const double P = 0.5 * (lo + hi);
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

  Eigen::VectorXd
  central_difference(NonlocalBedSystem     &system,
                     const Eigen::VectorXd &v,
                     const double           h)
  {
    auto                  x  = system.coordinates();
    const Eigen::VectorXd x0 = x;
    Eigen::VectorXd       Fp, Fm;
    x = x0 + h * v;
    system.residual(Fp);
    x = x0 - h * v;
    system.residual(Fm);
    x = x0;
    return (Fp - Fm) / (2 * h);
  }

  TEST(NonlocalPeriodic, JacobianInShearedCellIsCentralDifference)
  {
    const std::vector<ElasticMaterial> two_materials{{19e9, 0.30}, {7e9, 0.20}};
    const double                       R = 100e-6;
    for (const bool nonlocal : {false, true})
      for (unsigned int seed : {2u, 3u})
        {
          Crystal            c = simple_cubic(R, 1.97 * R, 3e-3, 0.01, seed);
          NonlocalBedOptions o;
          o.nonlocal                   = nonlocal;
          o.fixed_point_tolerance      = 1e-16;
          o.max_fixed_point_iterations = 100000;
          NonlocalBedSystem system(c.particles, two_materials, c.cell, o);
          Eigen::VectorXd   F, Jv, Kv;
          BlockSparseMatrix K;
          system.assemble(F, K);
          ASSERT_TRUE(F.allFinite());
          ASSERT_GE(system.n_loaded(), 20u);
          std::mt19937                     gen(seed);
          std::normal_distribution<double> normal;
          Eigen::VectorXd                  v(3 * c.particles.size());
          for (Eigen::Index k = 0; k < v.size(); ++k)
            v[k] = normal(gen);
          system.apply_jacobian(v, Jv);
          const Eigen::VectorXd fd = central_difference(system, v, 1e-8 * R);
          system.residual(F);
          EXPECT_LE((Jv - fd).norm(), 1e-6 * fd.norm())
            << nonlocal << ' ' << seed;
          if (!nonlocal)
            {
              Kv.resize(v.size());
              K.vmult(Kv, v);
              EXPECT_LE((Kv - fd).norm(), 1e-6 * fd.norm()) << seed;
            }
        }
  }
} // namespace

// Shared fixtures of the unit tests of the nonlocal contact formulation
// (Gonzalez & Cuitino 2012): small clusters in the square die, the
// closed forms of the chain between rigid walls and of the influence
// coefficient (Eqs. 5, 10, 11, solved here by bisection), central finite
// differences of the residual, and the wall-force balance of a bed at
// equilibrium.

#pragma once

#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/nonlocal/square_die_deposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace compax::dem::nonlocal_test
{
  inline constexpr double pi = 3.14159265358979323846;

  inline const std::vector<ElasticMaterial> two_materials{{19e9, 0.30},
                                                          {7e9, 0.20}};

  /// Spheres in a square die.
  struct Cluster
  {
    ParticleSystem particles;
    SquareDie      die;
  };

  /// A 2x2x2 block of spheres on a perturbed cubic lattice, pressed
  /// together by ~2 % of R and against the six walls of a square die.
  inline Cluster
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

  /// Chain of n spheres on the z axis between the punches of a wide die,
  /// punch approach Delta, with the middle spheres displaced from their
  /// equilibrium.
  inline Cluster
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

  /// The bimodal deposit of the square-die tests (sizes of the paper's
  /// two powders), `counts` spheres of each, and a die of the given width
  /// whose upper punch touches the top of the deposit.
  inline Cluster
  deposited_square_die_bed(const double                    width,
                           const std::vector<std::size_t> &counts,
                           const unsigned int              seed)
  {
    SquareDepositionParameters dp;
    dp.width = width;
    dp.sizes
      = {{77.46e-6, 0.0161, 75e-6, 80e-6}, {144.5e-6, 0.0724, 125e-6, 167e-6}};
    dp.counts = counts;
    dp.seed   = seed;
    Cluster c;
    c.particles = square_die_deposition(dp);
    double top  = 0.0;
    for (std::size_t i = 0; i < c.particles.size(); ++i)
      top = std::max(top, c.particles.positions[i][2] + c.particles.radii[i]);
    c.die.width              = width;
    c.die.upper_punch_height = top;
    return c;
  }

  /// Lower root of P = n (g + c P)^{3/2} (Eq. 10 with the nonlocal
  /// overlap c P of Eq. 11) by bisection.
  inline double
  lower_root(const double n, const double g, const double c)
  {
    double lo = n * std::pow(g, 1.5), hi = lo;
    while (hi - n * std::pow(g + c * hi, 1.5) < 0)
      hi *= 1.01;
    for (int i = 0; i < 200; ++i)
      {
        const double mid                                     = 0.5 * (lo + hi);
        (mid - n * std::pow(g + c * mid, 1.5) < 0 ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }

  /// P = n_w (Delta / 2N + c P)^{3/2} (Eqs. 10, 11 for a chain of N equal
  /// spheres between rigid walls approaching by Delta).
  inline double
  chain_force(unsigned int n, double R, double E, double nu, double Delta)
  {
    const double n_w = 4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R);
    const double c   = (1 + nu) * (3 - 2 * nu) / (4 * pi * R * E);
    return lower_root(n_w, Delta / (2.0 * n), c);
  }

  /// Eq. (5) per unit force: the displacement of a contact point of a
  /// sphere (R, E, nu) by a unit force at angle theta from it.
  inline double
  influence(const double R, const double E, const double nu, const double theta)
  {
    const double h = std::sin(theta / 2);
    return (1 + nu) / (4 * pi * R * E)
           * (-2 * (1 - nu) - 2 * (1 - 2 * nu) * h + (7 - 8 * nu) * h * h) / h;
  }

  /// Contact force of the simple cubic crystal of equal spheres (R, E, nu)
  /// at spacing a < 2R (hydrostatic compression, Eqs. 5, 9, 10): n_H =
  /// 4/3 E* sqrt(R*), E* = E / 2(1 - nu^2), R* = R / 2; on each sphere a
  /// contact sees the opposite one (theta = pi) and four at theta = pi / 2,
  /// and both spheres add.
  inline double
  simple_cubic_force(const double R,
                     const double E,
                     const double nu,
                     const double a,
                     const bool   nonlocal)
  {
    const double n_H   = 4.0 / 3.0 * E / (2 * (1 - nu * nu)) * std::sqrt(R / 2);
    const double gamma = 2 * R - a;
    const double k
      = nonlocal
          ? 2 * (influence(R, E, nu, pi) + 4 * influence(R, E, nu, pi / 2))
          : 0.0;
    return lower_root(n_H, gamma, k);
  }

  /// Standard normal vector of size n.
  inline Eigen::VectorXd
  random_vector(std::mt19937 &gen, const Eigen::Index n)
  {
    std::normal_distribution<double> normal;
    Eigen::VectorXd                  v(n);
    for (Eigen::Index k = 0; k < n; ++k)
      v[k] = normal(gen);
    return v;
  }

  /// Central difference of the residual along v (the coordinates are
  /// restored).
  inline Eigen::VectorXd
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

  /// Options whose Algorithm 1 converges to @p tolerance (up to 100000
  /// sweeps), so that finite differences of the residual are not lost in
  /// the fixed point's own error.
  inline NonlocalBedOptions
  converged_fixed_point(const double tolerance, const bool nonlocal = true)
  {
    NonlocalBedOptions o;
    o.nonlocal                   = nonlocal;
    o.fixed_point_tolerance      = tolerance;
    o.max_fixed_point_iterations = 100000;
    return o;
  }

  /// A Jacobian check along one direction: the central difference fd of
  /// the residual and K v.
  struct JacobianProducts
  {
    Eigen::VectorXd fd;
    Eigen::VectorXd Kv;
  };

  /// At the state where @p K was assembled, along a standard normal v
  /// (seeded with @p seed): expects J v to equal the central difference
  /// of the residual (step @p h) to 1e-6 of its norm, and K v as well
  /// without the nonlocal terms (for Hertz the assembled K is the exact
  /// Jacobian); returns that difference and K v. The system is evaluated
  /// back at that state.
  inline JacobianProducts
  expect_jacobian_is_central_difference(NonlocalBedSystem       &system,
                                        const BlockSparseMatrix &K,
                                        const unsigned int       seed,
                                        const double             h)
  {
    const bool            nonlocal = system.options().nonlocal;
    std::mt19937          gen(seed);
    const Eigen::VectorXd v = random_vector(gen, system.coordinates().size());
    Eigen::VectorXd       Jv, F;
    system.apply_jacobian(v, Jv);
    JacobianProducts p;
    p.fd = central_difference(system, v, h);
    system.residual(F); // back to the state of K
    EXPECT_LE((Jv - p.fd).norm(), 1e-6 * p.fd.norm())
      << "nonlocal " << nonlocal << " seed " << seed;
    p.Kv.resize(v.size());
    K.vmult(p.Kv, v);
    if (!nonlocal)
      {
        EXPECT_LE((p.Kv - p.fd).norm(), 1e-6 * p.fd.norm())
          << "nonlocal " << nonlocal << " seed " << seed;
      }
    return p;
  }

  /// Evaluates the system at its current state and expects both punches
  /// to carry P, to rel_tol P.
  inline void
  expect_punch_forces(NonlocalBedSystem &system,
                      const double       P,
                      const double       rel_tol)
  {
    Eigen::VectorXd F;
    system.residual(F);
    EXPECT_NEAR(system.wall_forces()[SquareDie::upper_punch], P, rel_tol * P);
    EXPECT_NEAR(system.wall_forces()[SquareDie::lower_punch], P, rel_tol * P);
  }

  /// Newton's third law at equilibrium without gravity: opposite walls of
  /// the square die carry the same force, to tol.
  template <typename WallForces>
  void
  expect_opposite_walls_balance(const WallForces &w, const double tol)
  {
    EXPECT_NEAR(w[SquareDie::lower_punch], w[SquareDie::upper_punch], tol);
    EXPECT_NEAR(w[SquareDie::x_lower], w[SquareDie::x_upper], tol);
    EXPECT_NEAR(w[SquareDie::y_lower], w[SquareDie::y_upper], tol);
  }
} // namespace compax::dem::nonlocal_test

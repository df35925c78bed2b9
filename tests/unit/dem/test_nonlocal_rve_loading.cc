// Periodic cells of elastic frictionless spheres driven along strain paths
// (NonlocalRveLoading): the simple cubic crystal under hydrostatic strain
// against the closed form of Eqs. (5), (9), (10) with its Love-Weber
// stress, and, for Hertz contacts (which derive from a potential), the
// work of the homogenized stress over a strain step against the change of
// the stored energy summed here pair by pair.

#include "dem/rve/nonlocal_rve_loading.h"
#include "dem/rve/periodic_packing.h"

#include "nonlocal_test_support.h"
#include "tests/support/narrow_polydisperse_cell.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace compax::dem;
  using namespace compax::dem::nonlocal_test;

  TEST(NonlocalRveLoading, SimpleCubicUnderHydrostaticStrainIsClosedForm)
  {
    const double R = 0.01, E = 1.85e6, nu = 0.46, eps = 0.01;
    for (const bool nonlocal : {false, true})
      {
        // 2 x 2 x 2 touching spheres in a cubic cell of side 4R.
        PeriodicBed bed;
        bed.reference_lattice = 4 * R * Eigen::Matrix3d::Identity();
        bed.cell.set_lattice(bed.reference_lattice);
        for (int k = 0; k < 2; ++k)
          for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
              bed.particles.add(Eigen::Vector3d(2 * R * i + R,
                                                2 * R * j + R,
                                                2 * R * k + R),
                                R,
                                0);
        NonlocalRveOptions o;
        o.materials        = {{E, nu}};
        o.nonlocal         = nonlocal;
        o.jamming_pressure = 0.0;
        NonlocalRveLoading  loading(o);
        const RveStepResult r
          = loading.deform_to(bed, (1 - eps) * Eigen::Matrix3d::Identity());
        ASSERT_TRUE(r.converged);
        const double          a = 2 * R * (1 - eps);
        const double          P = simple_cubic_force(R, E, nu, a, nonlocal);
        const Eigen::Matrix3d S = loading.stress(bed);
        EXPECT_NEAR(bed.relative_density(),
                    8 * 4.0 / 3.0 * pi * R * R * R
                      / std::pow(4 * R * (1 - eps), 3),
                    1e-12);
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR(S(i, i), -P / (a * a), 1e-8 * P / (a * a)) << nonlocal;
        EXPECT_EQ(loading.coordination(bed), 6.0);
      }
  }

  /// Stored Hertz energy sum 2/5 n_H gamma^{5/2} over the pairs of a cell
  /// (minimum image; the cell is wider than two diameters).
  double
  hertz_energy(const PeriodicBed &bed, const double E, const double nu)
  {
    const auto &p = bed.particles;
    double      U = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j)
        {
          const Eigen::Vector3d d
            = bed.cell.minimum_image(p.positions[j] - p.positions[i]);
          const double gamma = p.radii[i] + p.radii[j] - d.norm();
          if (gamma <= 0)
            continue;
          const double Rs = p.radii[i] * p.radii[j] / (p.radii[i] + p.radii[j]);
          const double n_H
            = 4.0 / 3.0 * E / (2 * (1 - nu * nu)) * std::sqrt(Rs);
          U += 0.4 * n_H * std::pow(gamma, 2.5);
        }
    return U;
  }

  TEST(NonlocalRveLoading, HertzStressDoesTheWorkOfTheStoredEnergy)
  {
    const double E = 10e9, nu = 0.3, R = 100e-6;
    // A loose cell (contact model only for the packing's relaxation).
    const ContactModel model(ElastoplasticMaterial{E, nu, 1e12, 2.0}, 0.0);
    PeriodicBed        bed = make_periodic_packing(
      compax::testing::narrow_polydisperse_cell(30, R, 1.2, 0.55, 5), model);
    NonlocalRveOptions o;
    o.materials        = {{E, nu}};
    o.nonlocal         = false;
    o.jamming_pressure = 1e6;
    NonlocalRveLoading loading(o);
    // Hydrostatic compression in ten steps to jam it.
    RveStepResult r;
    for (int k = 1; k <= 10; ++k)
      {
        const double rho = 0.55 + 0.015 * k;
        r                = loading.deform_to(bed,
                              std::cbrt(0.55 / rho)
                                * Eigen::Matrix3d::Identity());
        ASSERT_TRUE(r.converged) << rho;
      }
    ASSERT_GE(-loading.stress(bed).trace() / 3, o.jamming_pressure);
    r = loading.equilibrate(bed);
    ASSERT_TRUE(r.converged);
    ASSERT_TRUE(r.jammed);
    // A small uniaxial step: W = V sigma : d eps (trapezoidal) = dU.
    const double          U0 = hertz_energy(bed, E, nu);
    const double          V0 = bed.cell.volume();
    const Eigen::Matrix3d S0 = loading.stress(bed);
    ASSERT_LT(S0.trace(), 0.0);
    Eigen::Matrix3d de = Eigen::Matrix3d::Zero();
    de(2, 2)           = -1e-4;
    de(0, 1) = de(1, 0) = 0.5e-4;
    r                   = loading.apply_strain(bed, de);
    ASSERT_TRUE(r.converged);
    EXPECT_LE(r.relative_residual, o.solver.force_tolerance);
    const double          U1 = hertz_energy(bed, E, nu);
    const double          V1 = bed.cell.volume();
    const Eigen::Matrix3d S1 = loading.stress(bed);
    const double W = 0.5 * ((V0 * S0 + V1 * S1).cwiseProduct(de)).sum();
    ASSERT_GT(U1 - U0, 0.0);
    EXPECT_NEAR(W, U1 - U0, 1e-3 * (U1 - U0));
  }
} // namespace

// A periodic representative volume element of bonded elasto-plastic spheres
// driven along a uniaxial strain path with the installed compax library:
// Love-Weber stress per step, then the condensed (consistent) tangent C of
// the compacted cell, checked against central finite differences of the
// re-equilibrated stress, and the elastic moduli of its unloading tangent;
// the compacted cell is saved to an HDF5 archive (compacted_rve.h5 in the
// working directory) and read back. Exits non-zero unless the results are
// physical.

#include <coupling/elastic_moduli.h>
#include <coupling/rve_archive.h>
#include <dem/rve/homogenization.h>
#include <dem/rve/periodic_bed_system.h>
#include <dem/rve/periodic_packing.h>
#include <dem/rve/rve_loading.h>

#include <cmath>
#include <cstdio>
#include <exception>

namespace dem = compax::dem;

namespace
{
  void
  print_voigt(const char *title, const dem::Matrix6d &C)
  {
    std::printf("%s [GPa], Voigt order xx yy zz yz xz xy:\n", title);
    for (int i = 0; i < 6; ++i)
      {
        for (int j = 0; j < 6; ++j)
          std::printf(" %9.4f", C(i, j) / 1e9);
        std::printf("\n");
      }
  }
} // namespace

int
main()
{
  // Material 1 of Gonzalez 2018, Table 1.
  const dem::ContactModel model(dem::ElastoplasticMaterial{5e9, 0.25, 150e6, 2},
                                1.26e6);
  dem::PeriodicPackingSpec spec;
  spec.particle_count      = 150;
  spec.sizes.median_radius = 220e-6;
  spec.relative_density    = 0.55;
  spec.seed                = 1;
  dem::PeriodicBed bed     = dem::make_periodic_packing(spec, model);
  const double     rho0    = bed.relative_density();
  std::printf("periodic cell of %zu particles, relative density %.3f\n",
              spec.particle_count,
              rho0);

  int        failures = 0;
  const auto check    = [&failures](bool ok, const char *what) {
    if (!ok)
      {
        std::fprintf(stderr, "FAILED: %s\n", what);
        ++failures;
      }
  };

  // Uniaxial strain along z in equal density steps: F = diag(1, 1, rho0/rho).
  const double    rho_end = 0.75;
  const int       steps   = 12;
  dem::RveLoading loading(model);
  Eigen::Matrix3d increment = Eigen::Matrix3d::Zero();
  std::printf("\n%4s %8s %9s %12s %12s %9s\n",
              "step",
              "rho [-]",
              "eps_zz",
              "s_xx [MPa]",
              "s_zz [MPa]",
              "p [MPa]");
  for (int k = 1; k <= steps; ++k)
    {
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      F(2, 2)           = rho0 / (rho0 + (rho_end - rho0) * k / steps);
      const Eigen::Matrix3d    F_previous = bed.deformation;
      const dem::RveStepResult r          = loading.deform_to(bed, F);
      if (!r.converged)
        {
          std::fprintf(stderr, "loading step %d did not converge\n", k);
          return 1;
        }
      increment
        = bed.deformation * F_previous.inverse() - Eigen::Matrix3d::Identity();
      const Eigen::Matrix3d sigma = dem::love_weber_stress(bed);
      std::printf("%4d %8.4f %9.5f %12.4f %12.4f %9.4f\n",
                  k,
                  bed.relative_density(),
                  dem::logarithmic_strain(bed.deformation)(2, 2),
                  sigma(0, 0) / 1e6,
                  sigma(2, 2) / 1e6,
                  dem::mean_pressure(bed) / 1e6);
    }

  // Confined compaction: compressive stresses, larger along the axis.
  const Eigen::Matrix3d sigma = dem::love_weber_stress(bed);
  check(sigma(2, 2) < 0.0 && dem::mean_pressure(bed) > 0.0,
        "the compacted cell is in compression");
  check(std::abs(sigma(2, 2)) > std::abs(sigma(0, 0)),
        "axial stress exceeds lateral stress");

  // Condensed tangent at a trial state half a step further along the path,
  // equilibrated with frozen internal variables: at a converged state every
  // loading contact sits on the kink between its plastic and elastic
  // branches, where no difference quotient exists.
  dem::EquilibriumOptions tight;
  tight.force_tolerance  = 1e-10;
  tight.step_tolerance   = 1e-10;
  dem::PeriodicBed trial = bed;
  dem::map_affinely(trial,
                    (Eigen::Matrix3d::Identity() + 0.5 * increment)
                      * bed.deformation);
  dem::PeriodicAssembler assembler;
  dem::PeriodicBedSystem system(trial, model, assembler);
  if (!dem::TrustRegionNewton(tight).solve(system).converged)
    {
      std::fprintf(stderr, "the trial state did not converge\n");
      return 1;
    }
  dem::TangentCalculator tangent;
  const dem::Matrix6d    C  = tangent.compute(trial, model).condensed;
  dem::Matrix6d          fd = dem::Matrix6d::Zero();
  try
    {
      fd = dem::finite_difference_tangent(trial, model, 1e-6, tight);
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "finite-difference tangent: %s\n", e.what());
      return 1;
    }
  std::printf("\n");
  print_voigt("condensed tangent C = dsigma/deps", C);
  const double fd_error = (C - fd).norm() / fd.norm();
  std::printf("relative difference to central finite differences: %.2e\n",
              fd_error);
  check(fd_error < 1e-3, "the condensed tangent equals finite differences");
  check(C(2, 2) > 0.0, "stiffness along the compaction axis is positive");

  // Elastic moduli from the unloading tangent of the compacted cell (its
  // symmetric part: a Cauchy tangent carries -sigma tr(eps)).
  const dem::Matrix6d U
    = tangent.compute(bed, model, dem::ContactBranch::unloading).condensed;
  const dem::Matrix6d U_sym = 0.5 * (U + U.transpose());
  try
    {
      compax::coupling::compliance(U_sym); // throws unless positive definite
      const auto iso = compax::coupling::isotropic_projection(U_sym);
      std::printf("unloading tangent: isotropic E = %.3f GPa, nu = %.3f\n",
                  iso.youngs_modulus / 1e9,
                  iso.poisson_ratio);
      check(iso.youngs_modulus > 0.0 && iso.poisson_ratio > -1.0
              && iso.poisson_ratio < 0.5,
            "admissible isotropic elastic constants");
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "unloading tangent: %s\n", e.what());
      check(false, "the unloading tangent is positive definite");
    }

  // The archive (HDF5 through deal.II) restores the state exactly: same
  // positions, lattice and internal variables, hence the same stress.
  try
    {
      compax::coupling::save_rve("compacted_rve.h5", bed);
      const dem::PeriodicBed restored
        = compax::coupling::load_rve("compacted_rve.h5", model);
      const double difference
        = (dem::love_weber_stress(restored) - sigma).norm() / sigma.norm();
      std::printf("compacted_rve.h5 read back: stress difference %.1e\n",
                  difference);
      check(difference < 1e-12, "the archived cell has the same stress");
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "RVE archive: %s\n", e.what());
      check(false, "the compacted cell is archived and read back");
    }

  if (failures > 0)
    {
      std::fprintf(stderr, "%d check(s) failed\n", failures);
      return 1;
    }
  std::printf("all checks passed\n");
  return 0;
}

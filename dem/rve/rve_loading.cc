#include "dem/rve/rve_loading.h"

#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_bed_system.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  Eigen::Matrix3d
  logarithmic_strain(const Eigen::Matrix3d &F)
  {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(F * F.transpose());
    const Eigen::Vector3d                                log_stretch
      = 0.5 * eig.eigenvalues().array().log().matrix();
    return eig.eigenvectors() * log_stretch.asDiagonal()
           * eig.eigenvectors().transpose();
  }

  double
  mean_pressure(const PeriodicBed &bed)
  {
    return -love_weber_stress(bed).trace() / 3.0;
  }

  RveLoading::RveLoading(const ContactModel &model, RveLoadingOptions options)
      : model(model)
      , opts(options)
      , newton(options.equilibrium)
  {
  }

  bool
  RveLoading::substep(PeriodicBed           &bed,
                      const Eigen::Matrix3d &F,
                      RveStepResult         &total)
  {
    const bool jammed = mean_pressure(bed) >= opts.jamming_pressure;
    total.jammed      = jammed;
    saved             = bed;
    map_affinely(bed, F);
    PeriodicBedSystem system(bed, model, assembler);
    if (!jammed)
      {
        // Below jamming: relax with frozen histories (Consolidation's rule).
        const double R = bed.particles.mean_radius();
        const double floor
          = opts.force_floor_fraction * opts.jamming_pressure * M_PI * R * R;
        const FireResult f = fire.relax(system,
                                        opts.fire_tolerance,
                                        opts.fire_iterations,
                                        floor);
        total.relaxation_iterations += f.iterations;
        total.relative_residual = f.relative_residual;
        if (f.converged)
          return true;
        bed = saved;
        return false;
      }
    const EquilibriumResult r = newton.solve(system);
    total.iterations += r.iterations;
    total.cg_iterations += r.cg_iterations;
    total.relative_residual = r.relative_residual;
    if (!r.converged)
      {
        bed = saved;
        return false;
      }
    const BondChanges b
      = bed.contacts.update_histories(bed.particles, bed.cell);
    total.bonds.formed += b.formed;
    total.bonds.broken += b.broken;
    return true;
  }

  RveStepResult
  RveLoading::deform_to(PeriodicBed &bed, const Eigen::Matrix3d &F_target)
  {
    RveStepResult         total;
    const Eigen::Matrix3d F_start = bed.deformation;
    double                done    = 0.0;
    fraction = std::clamp(fraction, opts.stepping.min_fraction, 1.0);
    while (done < 1.0)
      {
        const double          t = std::min(1.0, done + fraction);
        const Eigen::Matrix3d F
          = t >= 1.0 ? F_target : F_start + t * (F_target - F_start);
        if (substep(bed, F, total))
          {
            ++total.substeps;
            done     = t;
            fraction = std::min(1.0, fraction * opts.stepping.growth);
          }
        else
          {
            ++total.cutbacks;
            fraction *= 0.5;
            if (fraction < opts.stepping.min_fraction)
              {
                fraction        = opts.stepping.min_fraction;
                total.converged = false;
                return total;
              }
          }
      }
    total.converged = true;
    return total;
  }

  RveStepResult
  RveLoading::apply_strain(PeriodicBed           &bed,
                           const Eigen::Matrix3d &strain_increment)
  {
    return deform_to(bed,
                     (Eigen::Matrix3d::Identity() + strain_increment)
                       * bed.deformation);
  }

  RveStepResult
  RveLoading::equilibrate(PeriodicBed &bed)
  {
    RveStepResult total;
    total.converged = substep(bed, bed.deformation, total);
    total.substeps  = total.converged ? 1 : 0;
    return total;
  }
} // namespace compax::dem

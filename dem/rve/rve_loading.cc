#include "dem/rve/rve_loading.h"

#include "dem/numbers.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_bed_system.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
    // Measured at stop 33: Gauss-Newton loose steps in a periodic cell
    // were cut back without end (a 60-sphere cell did not pack in 5 min).
    if (opts.unjammed_equilibrium == UnjammedEquilibrium::least_squares)
      throw std::invalid_argument(
        "RVE loading: unjammed equilibrium 'least-squares' (Algorithm 1 as "
        "printed) is the die's option only; use balanced-lbfgs, "
        "balanced-relaxation, relaxation+newton or relaxation");
  }

  double
  RveLoading::force_resolution(const PeriodicBed &bed) const
  {
    const double R = bed.particles.mean_radius();
    return opts.force_floor_fraction * opts.jamming_pressure * pi * R * R;
  }

  double
  RveLoading::balanced_force_floor(const PeriodicBed &bed) const
  {
    const double R = bed.particles.mean_radius();
    return std::max(opts.equilibrium.force_floor,
                    opts.equilibrium.force_tolerance * opts.jamming_pressure
                      * pi * R * R);
  }

  bool
  RveLoading::jammed(const PeriodicBed &bed)
  {
    if (opts.consolidation == RveConsolidation::frozen_history)
      return mean_pressure(bed) >= opts.jamming_pressure;
    if (loose < 0)
      loose = mean_pressure(bed) < opts.jamming_pressure ? 1 : 0;
    return loose == 0;
  }

  bool
  RveLoading::substep(PeriodicBed           &bed,
                      const Eigen::Matrix3d &F,
                      RveStepResult         &total)
  {
    const bool frozen = opts.consolidation == RveConsolidation::frozen_history;
    // The bonded path asks before the predictor moves the particles.
    const bool unjammed = opts.jamming_pressure > 0.0 && !jammed(bed);
    total.jammed        = !unjammed;
    saved               = bed;
    map_affinely(bed, F);
    PeriodicBedSystem system(bed, model, assembler);
    // The bonded path resolves forces as the die does; the frozen-history
    // path keeps its former rule (every force resolved).
    const double resolution         = force_resolution(bed);
    const double history_resolution = opts.resolved_history ? resolution : 0.0;
    if (unjammed)
      {
        // A balanced relaxation stops where Newton would: at the relative
        // force tolerance, or below the floor at which a loose cell counts
        // as force-free.
        const bool lbfgs_minimiser
          = !frozen && relaxes_by_lbfgs(opts.unjammed_equilibrium);
        const bool balanced
          = !frozen && relaxes_to_balance(opts.unjammed_equilibrium);
        Relaxation &minimiser = lbfgs_minimiser
                                  ? static_cast<Relaxation &>(lbfgs)
                                  : static_cast<Relaxation &>(fire);
        minimiser.give_up_when_stalled(balanced ? opts.balanced_stall_window
                                                : 0);
        const FireResult f
          = balanced ? minimiser.relax(system,
                                       opts.equilibrium.force_tolerance,
                                       opts.balanced_iterations,
                                       balanced_force_floor(bed))
                     : minimiser.relax(system,
                                       opts.fire_tolerance,
                                       opts.fire_iterations,
                                       resolution);
        total.relaxation_iterations += f.iterations;
        total.relative_residual = f.relative_residual;
        if (frozen)
          {
            // Consolidation's rule: nothing is committed below jamming.
            if (!f.converged)
              bed = saved;
            else
              total.relaxed = true;
            return f.converged;
          }
        const bool then_newton = opts.unjammed_equilibrium
                                 == UnjammedEquilibrium::relaxation_then_newton;
        const double p = mean_pressure(bed);
        if (p < opts.jamming_pressure && !then_newton)
          {
            // Still unjammed: the relaxed cell is the sub-step's
            // equilibrium, unless it did not get there (cut back: a
            // smaller sub-step starts closer to equilibrium, and Newton
            // has no stiffness along the mechanisms of a loose cell).
            if (!f.converged)
              {
                bed = saved;
                return false;
              }
            commit(bed, p, history_resolution, total);
            total.relaxed = true;
            return true;
          }
        // The cell jams in this sub-step, or Newton balances the relaxed
        // state: Newton finishes from it.
      }
    const EquilibriumResult r = newton.solve(system);
    total.iterations += r.work.iterations;
    total.cg_iterations += r.work.cg_iterations;
    total.relative_residual = r.relative_residual;
    if (!r.converged)
      {
        bed = saved;
        return false;
      }
    commit(bed, mean_pressure(bed), frozen ? 0.0 : history_resolution, total);
    total.relaxed = false;
    return true;
  }

  void
  RveLoading::commit(PeriodicBed   &bed,
                     const double   pressure,
                     const double   resolution,
                     RveStepResult &total)
  {
    const BondChanges b
      = bed.contacts.update_histories(bed.particles, bed.cell, resolution);
    total.bonds.formed += b.formed;
    total.bonds.broken += b.broken;
    if (opts.consolidation == RveConsolidation::frozen_history)
      return;
    // A cell that has jammed once stays a solid: its unloading is a
    // static equilibrium solved by Newton, however small its pressure.
    if (loose != 0)
      loose = pressure < opts.jamming_pressure ? 1 : 0;
    total.jammed = loose == 0;
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
} // namespace compax::dem

#include "dem/rve/nonlocal_rve_loading.h"

#include "dem/nonlocal/nonlocal_coordination.h"
#include "dem/numbers.h"
#include "dem/solver/trust_region_newton.h"

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  NonlocalRveLoading::NonlocalRveLoading(NonlocalRveOptions options)
      : opts(std::move(options))
      , solver(opts.solver, opts.krylov)
  {
  }

  NonlocalBedSystem
  NonlocalRveLoading::make_system(PeriodicBed &bed, const bool nonlocal) const
  {
    NonlocalBedOptions o = opts.bed;
    o.nonlocal           = nonlocal;
    return NonlocalBedSystem(bed.particles, opts.materials, bed.cell, o);
  }

  Eigen::Matrix3d
  NonlocalRveLoading::stress(PeriodicBed &bed) const
  {
    NonlocalBedSystem system = make_system(bed, opts.nonlocal);
    Eigen::VectorXd   F;
    system.residual(F);
    return system.stress();
  }

  double
  NonlocalRveLoading::coordination(PeriodicBed &bed) const
  {
    NonlocalBedSystem system = make_system(bed, opts.nonlocal);
    return coordination_number(system);
  }

  bool
  NonlocalRveLoading::substep(PeriodicBed           &bed,
                              const Eigen::Matrix3d &F,
                              RveStepResult         &total)
  {
    const bool jammed = -stress(bed).trace() / 3.0 >= opts.jamming_pressure;
    total.jammed      = jammed;
    const PeriodicBed saved = bed;
    map_affinely(bed, F);
    NonlocalBedSystem system = make_system(bed, jammed && opts.nonlocal);
    Eigen::VectorXd   residual;
    bool              ok = false;
    if (!jammed)
      {
        const double R = bed.particles.mean_radius();
        const double floor
          = opts.force_floor_fraction * opts.jamming_pressure * pi * R * R;
        const FireResult f = fire.relax(system,
                                        opts.fire_tolerance,
                                        opts.fire_iterations,
                                        floor);
        total.relaxation_iterations += f.iterations;
        total.relative_residual = f.relative_residual;
        ok                      = f.converged;
      }
    else
      {
        const ContactSums s = system.residual(residual);
        if (residual.allFinite() && s.n_loaded == 0)
          ok = true;
        else if (residual.allFinite())
          {
            const EquilibriumResult r = solver.solve(system);
            total.iterations += r.work.iterations + r.krylov_iterations;
            total.cg_iterations += r.work.cg_iterations;
            total.relaxation_iterations += r.work.fire_iterations;
            total.relative_residual = r.relative_residual;
            ok                      = r.converged;
          }
      }
    if (!ok)
      bed = saved;
    return ok;
  }

  RveStepResult
  NonlocalRveLoading::deform_to(PeriodicBed           &bed,
                                const Eigen::Matrix3d &F_target)
  {
    RveStepResult         total;
    const Eigen::Matrix3d F_start = bed.deformation;
    total.converged               = advance_in_substeps(
      fraction, opts.stepping, total.cutbacks, [&](double t) {
        const Eigen::Matrix3d F
          = t >= 1.0 ? F_target : F_start + t * (F_target - F_start);
        if (!substep(bed, F, total))
          return false;
        ++total.substeps;
        return true;
      });
    return total;
  }
} // namespace compax::dem

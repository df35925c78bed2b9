#include "dem/nonlocal/elastic_die_stepper.h"

#include "dem/nonlocal/nonlocal_coordination.h"
#include "dem/numbers.h"
#include "dem/solver/fire_relaxation.h"
#include "dem/solver/trust_region_newton.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace compax::dem
{
  namespace
  {
    /// Maps the particles affinely from walls a to walls b: heights between
    /// the punches, radial positions with the die (when present in both).
    void
    map_affinely(ParticleSystem &p, const DieWalls &a, const DieWalls &b)
    {
      const double ratio = b.height() / a.height();
      const double radial
        = a.die_present && b.die_present ? b.radius() / a.radius() : 1.0;
      for (auto &x : p.positions)
        {
          x[2] = b.lower_punch + (x[2] - a.lower_punch) * ratio;
          x[0] *= radial;
          x[1] *= radial;
        }
    }
  } // namespace

  ElasticDieStepper::ElasticDieStepper(ElasticDieOptions options)
      : opts(std::move(options))
      , solver(opts.solver, opts.krylov)
  {
  }

  NonlocalBedSystem
  ElasticDieStepper::make_system(Bed &bed, const bool nonlocal) const
  {
    NonlocalBedOptions o = opts.bed;
    o.nonlocal           = nonlocal;
    return NonlocalBedSystem(bed.particles, opts.materials, bed.walls, o);
  }

  ContactSums
  ElasticDieStepper::sums(Bed &bed) const
  {
    NonlocalBedSystem system = make_system(bed, opts.nonlocal);
    Eigen::VectorXd   F;
    return system.residual(F);
  }

  double
  ElasticDieStepper::coordination(Bed &bed) const
  {
    NonlocalBedSystem system = make_system(bed, opts.nonlocal);
    return coordination_number(system);
  }

  bool
  ElasticDieStepper::solve(Bed &bed, LoadStepResult &total)
  {
    NonlocalBedSystem system = make_system(bed, opts.nonlocal);
    Eigen::VectorXd   F;
    ContactSums       s = system.residual(F);
    if (!F.allFinite())
      return false;
    bool   converged = true;
    double relative  = 0.0;
    if (s.n_loaded > 0)
      {
        const EquilibriumResult r = solver.solve(system);
        total.work += r.work;
        total.work.iterations += r.krylov_iterations;
        converged = r.converged;
        relative  = r.relative_residual;
        s         = system.residual(F);
      }
    total.last.converged         = converged;
    total.last.relative_residual = relative;
    total.last.sums              = s;
    return converged && F.allFinite();
  }

  LoadStepResult
  ElasticDieStepper::equilibrate(Bed &bed)
  {
    LoadStepResult total;
    total.substeps  = 1;
    total.converged = solve(bed, total);
    return total;
  }

  LoadStepResult
  ElasticDieStepper::advance(Bed &bed, const DieWalls &target)
  {
    LoadStepResult total;
    const DieWalls start = bed.walls;
    total.converged      = advance_in_substeps(
      fraction, opts.stepping, total.cutbacks, [&](double t) {
        const DieWalls next = t >= 1.0 ? target : interpolate(start, target, t);
        const ParticleSystem saved_particles = bed.particles;
        const DieWalls       saved_walls     = bed.walls;
        map_affinely(bed.particles, bed.walls, next);
        bed.walls = next;
        ++total.substeps;
        if (solve(bed, total))
          return true;
        bed.particles = saved_particles;
        bed.walls     = saved_walls;
        return false;
      });
    return total;
  }

  ConsolidationResult
  ElasticDieStepper::consolidate(Bed                        &bed,
                                 const double                max_density,
                                 const ConsolidationOptions &o)
  {
    const auto          t0 = std::chrono::steady_clock::now();
    ConsolidationResult result;
    NonlocalBedSystem   system = make_system(bed, false);
    FireRelaxation      fire;
    Eigen::VectorXd     F;
    const double        R = bed.particles.mean_radius();
    const double        floor
      = o.force_floor_fraction * o.jamming_pressure * pi * R * R;
    const double jam_force = o.jamming_pressure * bed.walls.punch_area();
    const double solid     = bed.particles.solid_volume();
    double       increment = o.initial_strain_increment;
    result.sums            = system.residual(F);
    while (result.sums.wall_force[int(Wall::upper_punch)] < jam_force)
      {
        const double H_min = solid / (bed.walls.punch_area() * max_density);
        if (bed.walls.height() <= H_min * (1.0 + 1e-12))
          break;
        DieWalls next = bed.walls;
        next.upper_punch
          = bed.walls.lower_punch
            + std::max(H_min, bed.walls.height() * (1.0 - increment));
        map_affinely(bed.particles, bed.walls, next);
        bed.walls = next;
        system.invalidate();
        const FireResult fr = fire.relax(system,
                                         o.relative_tolerance,
                                         o.max_relaxation_iterations,
                                         floor);
        ++result.increments;
        result.iterations += fr.iterations;
        result.sums = system.residual(F);
        if (!fr.converged || !F.allFinite())
          {
            result.failed = true;
            break;
          }
        // Loose: larger increments; carrying load: the initial one.
        increment = result.sums.wall_force[int(Wall::upper_punch)] > 0.0
                      ? o.initial_strain_increment
                      : std::min(o.max_strain_increment, 1.5 * increment);
      }
    result.jammed = result.sums.wall_force[int(Wall::upper_punch)] >= jam_force;
    result.relative_residual = result.sums.mean_force > 0.0 && F.allFinite()
                                 ? max_particle_norm(F) / result.sums.mean_force
                                 : 0.0;
    result.seconds
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
    return result;
  }
} // namespace compax::dem

#include "dem/solver/consolidation.h"

#include "dem/numbers.h"
#include "dem/solver/punch_gap_map.h"
#include "dem/solver/trust_region_newton.h"
#include "dem/wall_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace compax::dem
{
  Consolidation::Consolidation(const ConsolidationOptions options)
      : opts(options)
  {
  }

  RelaxationResult
  Consolidation::relax(Bed &bed, const ContactModel &model)
  {
    if (force_floor <= 0.0)
      force_floor = opts.force_floor_fraction * opts.jamming_pressure * pi
                    * std::pow(bed.particles.mean_radius(), 2);
    const FireResult f = fire.relax(bed,
                                    model,
                                    opts.relative_tolerance,
                                    opts.max_relaxation_iterations,
                                    force_floor);
    assemblies += f.assemblies;
    RelaxationResult r;
    r.converged         = f.converged;
    r.iterations        = f.iterations;
    r.sums              = f.sums;
    r.relative_residual = f.relative_residual;
    return r;
  }

  ConsolidationResult
  Consolidation::run(Bed &bed, const ContactModel &model, double max_density)
  {
    const auto          t0 = std::chrono::steady_clock::now();
    ConsolidationResult result;
    assemblies = 0;
    if (strain_increment <= 0.0)
      strain_increment = opts.initial_strain_increment;
    const double area  = bed.walls.punch_area();
    const double solid = bed.particles.solid_volume();

    // The deposit itself first (it touches only up to round-off).
    RelaxationResult r = relax(bed, model);
    result.iterations += r.iterations;
    Bed    saved;
    double p_last = 0.0, strain_last = 0.0;
    bool   retry = false;
    while (r.converged)
      {
        const double p = r.sums.wall_force[int(Wall::upper_punch)] / area;
        if (p >= opts.jamming_pressure)
          {
            result.jammed = true;
            break;
          }
        const double h_min = solid / (area * max_density);
        if (bed.walls.height() <= h_min * (1.0 + 1e-12))
          break;
        // Approaching jamming the pressure rises steeply: aim at the
        // jamming pressure by the secant of the last two increments (not
        // after a failed increment, which was reduced on purpose).
        if (!retry)
          {
            if (p > 1e-2 * opts.jamming_pressure && p > p_last)
              strain_increment = 1.2 * (opts.jamming_pressure - p)
                                 * (strain_last / (p - p_last));
            else
              strain_increment *= 1.5;
            strain_increment = std::clamp(strain_increment,
                                          opts.min_strain_increment,
                                          opts.max_strain_increment);
          }
        retry  = false;
        p_last = p;

        saved                       = bed;
        const RelaxationResult good = r;
        DieWalls               next = bed.walls;
        next.upper_punch
          = bed.walls.lower_punch
            + std::max(h_min, bed.walls.height() * (1.0 - strain_increment));
        strain_last = 1.0 - next.height() / bed.walls.height();
        map_heights(bed.particles, bed.walls, next, GapParticles::all);
        bed.walls = next;
        r         = relax(bed, model);
        result.iterations += r.iterations;
        if (!r.converged)
          {
            bed = saved;
            strain_increment *= 0.25;
            retry = true;
            if (strain_increment < opts.min_strain_increment)
              {
                result.failed = true;
                break;
              }
            r = good;
            continue;
          }
        ++result.increments;
      }
    if (!r.converged)
      result.failed = true;
    result.sums              = r.sums;
    result.relative_residual = r.relative_residual;
    result.assemblies        = assemblies;
    result.seconds           = seconds_since(t0);
    return result;
  }
} // namespace compax::dem

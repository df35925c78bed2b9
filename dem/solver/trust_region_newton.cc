#include "dem/solver/trust_region_newton.h"

#include "dem/solver/die_bed_system.h"
#include "dem/solver/step_limits.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <ostream>

namespace compax::dem
{
  namespace
  {
    using clock_type = std::chrono::steady_clock;

    double
    seconds_since(const clock_type::time_point t0)
    {
      return std::chrono::duration<double>(clock_type::now() - t0).count();
    }
  } // namespace

  TrustRegionNewton::TrustRegionNewton(const EquilibriumOptions options)
      : opts(options)
  {
  }

  EquilibriumResult
  TrustRegionNewton::solve(Bed &bed, const ContactModel &model)
  {
    DieBedSystem system(bed, model, assembler);
    return solve(system);
  }

  EquilibriumResult
  TrustRegionNewton::solve(EquilibriumSystem &system)
  {
    EquilibriumResult result;
    const double      R_mean = system.mean_radius();
    radius.start(system, opts.initial_radius, opts.max_radius);
    trial.forget();

    auto assemble = [&]() {
      const auto t0 = clock_type::now();
      result.sums   = system.assemble(F, K);
      result.assembly_seconds += seconds_since(t0);
      ++result.assemblies;
    };

    assemble();
    const double F0      = std::max(F.norm(), 1e-300);
    double       best    = std::numeric_limits<double>::infinity();
    int          best_at = 0;
    for (int it = 0;; ++it)
      {
        result.relative_residual = relative_residual(F, result.sums);
        if (result.relative_residual < 0.1 * best)
          {
            best    = result.relative_residual;
            best_at = it;
          }
        if (it - best_at >= opts.stall_iterations && opts.fire_iterations > 0)
          {
            // Newton crawls: the bed is rearranging. Relax with FIRE.
            const auto       tf = clock_type::now();
            const FireResult fr = fire.relax(system,
                                             opts.fire_tolerance,
                                             opts.fire_iterations,
                                             opts.force_floor);
            result.fire_seconds += seconds_since(tf);
            result.fire_iterations += fr.iterations;
            assemble();
            result.relative_residual = relative_residual(F, result.sums);
            best                     = result.relative_residual;
            best_at                  = it;
            radius.restart();
            trial.forget();
          }
        const bool force_ok = result.relative_residual <= opts.force_tolerance
                              || max_particle_norm(F) <= opts.force_floor;
        const bool step_ok = trial.last_move() <= opts.step_tolerance * R_mean;
        if (force_ok && step_ok)
          {
            result.converged = true;
            break;
          }
        if (it >= opts.max_iterations
            || !std::isfinite(result.relative_residual))
          break;

        // Trust-region subproblem.
        const auto t0 = clock_type::now();
        M.compute(K, opts.preconditioner_floor);
        const double eta = std::min(opts.max_forcing, std::sqrt(F.norm() / F0))
                           * (force_ok ? 0.1 : 1.0);
        const SteihaugResult sub
          = cg.solve(K, M, F, radius.value(), eta, opts.max_cg_iterations, s);
        result.linear_seconds += seconds_since(t0);
        result.cg_iterations += sub.iterations;
        ++result.iterations;
        double pred = sub.predicted_decrease, step_norm = sub.step_norm;
        s_full = s;
        if (opts.limit_to_gaps && limit_step_to_gaps(system, s, factor))
          {
            // The clipped step's own model decrease and length; if clipping
            // single particles lost the model decrease, shorten the whole
            // step uniformly instead (a Steihaug step is a descent
            // direction, g.s < 0).
            Ks.resize(s.size());
            K.vmult(Ks, s);
            pred = -(F.dot(s) + 0.5 * s.dot(Ks));
            if (!(pred > 0.0))
              {
                s = factor.minCoeff() * s_full;
                K.vmult(Ks, s);
                pred = -(F.dot(s) + 0.5 * s.dot(Ks));
              }
            M.multiply(Ks, s);
            step_norm = std::sqrt(std::max(s.dot(Ks), 0.0));
          }
        // No particle may move more than half the Verlet skin in one step
        // (it could pass through a wall or a neighbour): shrink and retry.
        const double longest = max_particle_norm(s);
        if (longest > 0.5 * system.skin())
          {
            radius.set(step_norm * 0.25 * system.skin() / longest);
            continue;
          }
        if (!(pred > 0.0))
          {
            // No decrease predicted: the residual is numerically zero in
            // every loaded direction.
            result.converged = force_ok;
            break;
          }

        const ContactSums old_sums = result.sums;
        const double      rho      = trial.take(system, s, F, pred, assemble);
        if (opts.trace)
          *opts.trace << "  newton it " << it << " residual "
                      << result.relative_residual << " mean force "
                      << old_sums.mean_force << " radius " << radius.value()
                      << " cg " << sub.iterations << " boundary "
                      << sub.on_boundary << " negative curvature "
                      << sub.negative_curvature << " predicted " << pred
                      << " rho " << rho << " step " << max_particle_norm(s)
                      << '\n';

        radius.update(rho, step_norm, sub.on_boundary);
        if (!trial.keep_or_undo(
              rho, std::isfinite(F.squaredNorm()), system, s, assemble))
          {
            ++result.rejected_steps;
            if (radius.value() < 1e-12 * R_mean)
              break;
          }
      }
    return result;
  }
} // namespace compax::dem

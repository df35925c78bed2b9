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

  double
  max_particle_norm(const Eigen::VectorXd &F)
  {
    double m = 0.0;
    for (Eigen::Index i = 0; i + 2 < F.size(); i += 3)
      m = std::max(m, F[i] * F[i] + F[i + 1] * F[i + 1] + F[i + 2] * F[i + 2]);
    return std::sqrt(m);
  }

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
    // The trust region bounds the M-norm of the whole step, so that a
    // radius of r R sqrt(N) lets every particle move by about r R.
    const double length
      = R_mean * std::sqrt(static_cast<double>(system.n_particles()));
    const double max_radius = opts.max_radius * length;
    if (radius <= 0.0)
      radius = opts.initial_radius * length;
    radius
      = std::clamp(radius, 1e-3 * opts.initial_radius * length, max_radius);

    auto assemble = [&]() {
      const auto t0 = clock_type::now();
      result.sums   = system.assemble(F, K);
      result.assembly_seconds += seconds_since(t0);
      ++result.assemblies;
    };
    auto relative = [&](const Eigen::VectorXd &f, const ContactSums &sums) {
      const double fmax = max_particle_norm(f);
      if (sums.mean_force > 0.0)
        return fmax / sums.mean_force;
      return fmax == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    };

    assemble();
    double       last_step = 0.0;
    bool         stepped   = false;
    const double F0        = std::max(F.norm(), 1e-300);
    double       best      = std::numeric_limits<double>::infinity();
    int          best_at   = 0;
    for (int it = 0;; ++it)
      {
        result.relative_residual = relative(F, result.sums);
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
            result.relative_residual = relative(F, result.sums);
            best                     = result.relative_residual;
            best_at                  = it;
            radius                   = opts.initial_radius * length;
            stepped                  = false;
          }
        const bool force_ok = result.relative_residual <= opts.force_tolerance
                              || max_particle_norm(F) <= opts.force_floor;
        const bool step_ok
          = !stepped || last_step <= opts.step_tolerance * R_mean;
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
          = cg.solve(K, M, F, radius, eta, opts.max_cg_iterations, s);
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
            radius = step_norm * 0.25 * system.skin() / longest;
            continue;
          }
        if (!(pred > 0.0))
          {
            // No decrease predicted: the residual is numerically zero in
            // every loaded direction.
            result.converged = force_ok;
            break;
          }

        // Trial point.
        auto x = system.coordinates();
        x_old  = x;
        F_old  = F;
        x += s;
        const ContactSums old_sums = result.sums;
        assemble();
        const double actual = -0.5 * (F_old + F).dot(s);
        const double rho    = actual / pred;
        if (opts.trace)
          *opts.trace << "  newton it " << it << " residual "
                      << result.relative_residual << " mean force "
                      << old_sums.mean_force << " radius " << radius << " cg "
                      << sub.iterations << " boundary " << sub.on_boundary
                      << " negative curvature " << sub.negative_curvature
                      << " predicted " << pred << " rho " << rho << " step "
                      << max_particle_norm(s) << '\n';

        if (rho < 0.25)
          radius = 0.25 * step_norm;
        else if (rho > 0.75 && sub.on_boundary)
          radius = std::min(2.0 * radius, max_radius);

        if (rho > 0.05 && std::isfinite(F.squaredNorm()))
          {
            stepped   = true;
            last_step = max_particle_norm(s);
          }
        else
          {
            ++result.rejected_steps;
            x           = x_old;
            F           = F_old;
            result.sums = old_sums;
            assemble(); // K at x_old (the contact list may have changed)
            if (radius < 1e-12 * R_mean)
              break;
          }
      }
    return result;
  }
} // namespace compax::dem

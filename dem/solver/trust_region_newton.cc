#include "dem/solver/trust_region_newton.h"

#include "dem/solver/die_bed_system.h"
#include "dem/solver/step_limits.h"
#include "dem/wall_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <ostream>

namespace compax::dem
{
  using clock_type = std::chrono::steady_clock;

  TrustRegionNewton::TrustRegionNewton(const EquilibriumOptions  options,
                                       const NewtonKrylovOptions krylov)
      : opts(options)
      , krylov(krylov)
  {
  }

  void
  assemble_timed(EquilibriumSystem &system,
                 Eigen::VectorXd   &F,
                 BlockSparseMatrix &K,
                 EquilibriumResult &result)
  {
    const auto t0 = clock_type::now();
    result.sums   = system.assemble(F, K);
    result.work.assembly_seconds += seconds_since(t0);
    ++result.work.assemblies;
  }

  bool
  forces_balanced(const EquilibriumResult  &result,
                  const Eigen::VectorXd    &F,
                  const EquilibriumOptions &options)
  {
    return result.relative_residual <= options.force_tolerance
           || max_particle_norm(F) <= options.force_floor;
  }

  EquilibriumResult
  TrustRegionNewton::solve(Bed &bed, const ContactModel &model)
  {
    DieBedSystem system(bed, model, assembler);
    return solve(system);
  }

  void
  TrustRegionNewton::apply_model_hessian(EquilibriumSystem     &system,
                                         const Eigen::VectorXd &v,
                                         Eigen::VectorXd       &Hv) const
  {
    if (!opts.matrix_free_model || !system.apply_model_hessian(v, Hv))
      K.vmult(Hv, v);
  }

  EquilibriumResult
  TrustRegionNewton::solve(EquilibriumSystem &system)
  {
    constexpr auto shorten_then_stop
      = EquilibriumOptions::LostDecrease::shorten_then_stop;
    EquilibriumResult result;
    const double      R_mean = system.mean_radius();
    radius.start(system,
                 opts.initial_radius,
                 opts.max_radius,
                 opts.reset_radius);
    trial.forget();

    auto       assemble = [&]() { assemble_timed(system, F, K, result); };
    const auto relative = [&]() {
      return F.allFinite() ? relative_residual(F, result.sums)
                           : std::numeric_limits<double>::infinity();
    };
    // The subproblem's operator: the model Hessian.
    struct ModelHessian
    {
      const TrustRegionNewton &solver;
      EquilibriumSystem       &system;

      void
      vmult(Eigen::VectorXd &Hv, const Eigen::VectorXd &v) const
      {
        solver.apply_model_hessian(system, v, Hv);
      }
    };

    const auto converged = [&](const bool force_ok) {
      return force_ok && trial.last_move() <= opts.step_tolerance * R_mean;
    };

    assemble();
    const double F0        = std::max(F.norm(), 1e-300);
    double       best      = std::numeric_limits<double>::infinity();
    int          best_at   = 0;
    double       krylov_at = std::numeric_limits<double>::infinity();
    for (int it = 0;; ++it)
      {
        result.relative_residual = relative();
        if (!std::isfinite(result.relative_residual))
          break;
        if (result.relative_residual < 0.1 * best)
          {
            best    = result.relative_residual;
            best_at = it;
          }
        bool force_ok = forces_balanced(result, F, opts);
        if (converged(force_ok))
          {
            result.converged = true;
            break;
          }
        if (result.relative_residual < opts.krylov_switch
            && result.relative_residual < 0.1 * krylov_at)
          {
            // Close to equilibrium: Newton on the exact Jacobian finishes.
            krylov_at                   = result.relative_residual;
            const NewtonKrylovResult nk = krylov.solve(system);
            result.krylov_iterations += nk.iterations;
            if (opts.trace)
              *opts.trace << "  newton it " << it << " newton-krylov from "
                          << result.relative_residual << ": " << nk.iterations
                          << " iterations, "
                          << (nk.converged ? "converged" : "failed")
                          << ", residual " << nk.relative_residual << '\n';
            assemble();
            result.relative_residual = relative();
            if (nk.converged)
              {
                result.converged = true;
                break;
              }
            best_at = it; // give the trust region its own chance
          }
        if (it - best_at >= opts.stall_iterations && opts.fire_iterations > 0)
          {
            // Newton crawls: the bed is rearranging. Relax it.
            const double target
              = opts.fire_below_residual
                  ? std::min(opts.fire_tolerance,
                             std::max(opts.force_tolerance,
                                      0.01 * result.relative_residual))
                  : opts.fire_tolerance;
            const auto  tf = clock_type::now();
            Relaxation &relaxation
              = opts.stall_relaxation
                    == EquilibriumOptions::StallRelaxation::lbfgs
                  ? static_cast<Relaxation &>(lbfgs)
                  : static_cast<Relaxation &>(fire);
            const FireResult fr = relaxation.relax(system,
                                                   target,
                                                   opts.fire_iterations,
                                                   opts.force_floor);
            result.work.fire_seconds += seconds_since(tf);
            result.work.fire_iterations += fr.iterations;
            if (opts.trace)
              *opts.trace << "  newton it " << it << " stalled: relaxed in "
                          << fr.iterations << '\n';
            assemble();
            result.relative_residual = relative();
            best                     = result.relative_residual;
            best_at                  = it;
            radius.restart();
            trial.forget();
            krylov_at = std::numeric_limits<double>::infinity();
            if (!std::isfinite(result.relative_residual))
              break;
            if (opts.test_after_fallback)
              {
                force_ok = forces_balanced(result, F, opts);
                if (converged(force_ok))
                  {
                    result.converged = true;
                    break;
                  }
              }
          }
        if (it >= opts.max_iterations)
          break;

        // Trust-region subproblem.
        const auto t0 = clock_type::now();
        M.compute(K, opts.preconditioner_floor);
        const double eta = std::min(opts.max_forcing, std::sqrt(F.norm() / F0))
                           * (force_ok ? 0.1 : 1.0);
        const SteihaugResult sub = cg.solve(ModelHessian{*this, system},
                                            M,
                                            F,
                                            radius.value(),
                                            eta,
                                            opts.max_cg_iterations,
                                            s);
        result.work.linear_seconds += seconds_since(t0);
        result.work.cg_iterations += sub.iterations;
        ++result.work.iterations;
        double pred = sub.predicted_decrease, step_norm = sub.step_norm;
        s_full = s;
        if (opts.limit_to_gaps && limit_step_to_gaps(system, s, factor))
          {
            // The clipped step's own model decrease and length; if clipping
            // single particles lost the model decrease, shorten the whole
            // step uniformly instead (a Steihaug step is a descent
            // direction, g.s < 0).
            Ks.resize(s.size());
            apply_model_hessian(system, s, Ks);
            pred = -(F.dot(s) + 0.5 * s.dot(Ks));
            if (!(pred > 0.0) && opts.lost_decrease == shorten_then_stop)
              {
                s = factor.minCoeff() * s_full;
                apply_model_hessian(system, s, Ks);
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
            // every loaded direction, or the clipped step lost it.
            if (force_ok || opts.lost_decrease == shorten_then_stop)
              {
                result.converged = force_ok;
                break;
              }
            radius.set(0.25 * radius.value());
            ++result.rejected_steps;
            if (radius.value() < 1e-12 * R_mean)
              break;
            continue;
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

        // A non-finite ratio counts as a poor prediction.
        radius.update(std::isfinite(rho) ? rho : 0.0,
                      step_norm,
                      sub.on_boundary);
        if (!trial.keep_or_undo(rho, F.allFinite(), system, s, assemble))
          {
            ++result.rejected_steps;
            if (radius.value() < 1e-12 * R_mean)
              break;
          }
      }
    return result;
  }
} // namespace compax::dem

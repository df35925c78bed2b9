#include "dem/nonlocal/nonlocal_trust_region.h"

#include "dem/solver/step_limits.h"
#include "dem/solver/trust_region_newton.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace compax::dem
{
  namespace
  {
    /// The model Hessian of NonlocalTrustRegion, the frozen-angle Jacobian
    /// H of the system, as the operator of SteihaugCG.
    struct FrozenAngleJacobian
    {
      NonlocalBedSystem &system;

      void
      vmult(Eigen::VectorXd &Hv, const Eigen::VectorXd &v) const
      {
        system.apply_jacobian(v, Hv, false);
      }
    };
  } // namespace

  NonlocalTrustRegion::NonlocalTrustRegion(
    const NonlocalTrustRegionOptions options,
    const NewtonKrylovOptions        krylov_options)
      : opts(options)
      , krylov(krylov_options)
  {
  }

  NonlocalTrustRegionResult
  NonlocalTrustRegion::solve(NonlocalBedSystem &system)
  {
    NonlocalTrustRegionResult result;
    const double              R = system.mean_radius();
    radius.start(system,
                 opts.initial_radius,
                 opts.max_radius,
                 opts.reset_radius);
    const double length = radius.length();
    trial.forget();

    ContactSums sums;
    const auto  relative = [&]() {
      return F.allFinite() ? relative_residual(F, sums)
                            : std::numeric_limits<double>::infinity();
    };
    const auto assemble = [&]() { sums = system.assemble(F, K); };

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
        const bool force_ok = result.relative_residual <= opts.force_tolerance;
        if (force_ok && trial.last_move() <= opts.step_tolerance * R)
          {
            result.converged = true;
            break;
          }
        // Close to equilibrium: exact Newton finishes.
        if (result.relative_residual < opts.krylov_switch
            && result.relative_residual < 0.1 * krylov_at)
          {
            krylov_at                   = result.relative_residual;
            const NewtonKrylovResult nk = krylov.solve(system);
            result.krylov_iterations += nk.iterations;
            if (opts.trace)
              *opts.trace << "  tr it " << it << " newton-krylov from "
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
            // FIRE (damped dynamics) converges for the nonconservative
            // field too, where the work measure of the trust region can
            // cycle; ask it for two decades below the current residual.
            const FireResult fr
              = fire.relax(system,
                           std::min(opts.fire_tolerance,
                                    std::max(opts.force_tolerance,
                                             0.01 * result.relative_residual)),
                           opts.fire_iterations);
            result.fire_iterations += fr.iterations;
            if (opts.trace)
              *opts.trace << "  tr it " << it << " stalled: FIRE "
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
          }
        if (it >= opts.max_iterations)
          break;

        M.compute(K, opts.preconditioner_floor);
        const double eta = std::min(opts.max_forcing, std::sqrt(F.norm() / F0))
                           * (force_ok ? 0.1 : 1.0);
        const SteihaugResult sub = cg.solve(FrozenAngleJacobian{system},
                                            M,
                                            F,
                                            radius.value(),
                                            eta,
                                            opts.max_cg_iterations,
                                            s);
        result.cg_iterations += sub.iterations;
        ++result.iterations;
        double pred = sub.predicted_decrease, step_norm = sub.step_norm;
        if (limit_step_to_gaps(system, s, factor))
          {
            system.apply_jacobian(s, Hp, false);
            pred = -(F.dot(s) + 0.5 * s.dot(Hp));
            Ms.resize(s.size());
            M.multiply(Ms, s);
            step_norm = std::sqrt(std::max(s.dot(Ms), 0.0));
          }
        if (!(pred > 0.0))
          {
            // No decrease predicted: the residual is numerically zero in
            // every loaded direction, or the clipped step lost it.
            if (force_ok)
              {
                result.converged = true;
                break;
              }
            radius.set(0.25 * radius.value());
            ++result.rejected_steps;
            if (radius.value() < 1e-12 * R)
              break;
            continue;
          }

        const double rho = trial.take(system, s, F, pred, assemble);
        if (opts.trace)
          *opts.trace << "  tr it " << it << " rel " << result.relative_residual
                      << " radius " << radius.value() / length << " cg "
                      << sub.iterations << " boundary " << sub.on_boundary
                      << " rho " << rho << " step " << max_particle_norm(s) / R
                      << '\n';
        // A non-finite ratio counts as a poor prediction.
        radius.update(std::isfinite(rho) ? rho : 0.0,
                      step_norm,
                      sub.on_boundary);
        if (!trial.keep_or_undo(rho, F.allFinite(), system, s, assemble))
          {
            ++result.rejected_steps;
            if (radius.value() < 1e-12 * length)
              break;
          }
      }
    return result;
  }
} // namespace compax::dem

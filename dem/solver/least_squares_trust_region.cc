#include "dem/solver/least_squares_trust_region.h"

#include "dem/solver/die_bed_system.h"
#include "dem/solver/residual_norms.h"
#include "dem/wall_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace compax::dem
{
  using clock_type = std::chrono::steady_clock;

  void
  LeastSquaresTrustRegion::NormalOperator::vmult(
    Eigen::VectorXd       &dst,
    const Eigen::VectorXd &src) const
  {
    K.vmult(work, src);
    K.vmult(dst, work);
    dst /= scale;
  }

  LeastSquaresTrustRegion::LeastSquaresTrustRegion(
    const EquilibriumOptions options)
      : opts(options)
  {
  }

  EquilibriumResult
  LeastSquaresTrustRegion::solve(Bed &bed, const ContactModel &model)
  {
    DieBedSystem system(bed, model, assembler);
    return solve(system);
  }

  FireResult
  as_relaxation(const EquilibriumResult &r)
  {
    FireResult f;
    f.converged         = r.converged;
    f.iterations        = r.work.iterations;
    f.relative_residual = r.relative_residual;
    f.sums              = r.sums;
    f.assemblies        = r.work.assemblies;
    return f;
  }

  EquilibriumResult
  LeastSquaresTrustRegion::solve(EquilibriumSystem &system)
  {
    EquilibriumResult result;
    const double      TOL1 = opts.step_tolerance * system.mean_radius();
    radius.start(system, opts.initial_radius, opts.max_radius, true);

    auto assemble = [&]() { assemble_timed(system, F, K, result); };

    assemble();
    // BlockSparseMatrix::vmult writes into sized vectors.
    g.resize(F.size());
    work.resize(F.size());
    const double F0 = std::max(F.norm(), 1e-300);
    for (int it = 0;; ++it)
      {
        result.relative_residual = F.allFinite()
                                     ? relative_residual(F, result.sums)
                                     : std::numeric_limits<double>::infinity();
        if (!std::isfinite(result.relative_residual))
          break;
        result.converged = forces_balanced(result, F, opts);
        if (result.converged || it >= opts.max_iterations)
          break;

        // Line 7: the Gauss-Newton model's gradient K F and Hessian K^2,
        // both divided by the preconditioner's scale c.
        const auto t0 = clock_type::now();
        M.compute(K, opts.preconditioner_floor);
        const double c = M.scale();
        K.vmult(g, F);
        g /= c;
        const NormalOperator KK{K, work, c};
        const double eta = std::min(opts.max_forcing, std::sqrt(F.norm() / F0));
        const SteihaugResult sub
          = cg.solve(KK, M, g, radius.value(), eta, opts.max_cg_iterations, s);
        result.work.linear_seconds += seconds_since(t0);
        result.work.cg_iterations += sub.iterations;
        ++result.work.iterations;
        const double pred = sub.predicted_decrease;
        // No particle may move more than half the Verlet skin in one step.
        // Gaps to contacts the model does not see need no clipping here
        // (EquilibriumOptions::limit_to_gaps): a step that closes one
        // raises |F| and is rejected by the ratio test.
        const double longest = max_particle_norm(s);
        if (longest > 0.5 * system.skin())
          {
            radius.set(sub.step_norm * 0.25 * system.skin() / longest);
            continue;
          }
        if (!(pred > 0.0))
          {
            // K F = 0 to round-off: a stationary point of |F|^2, where
            // Algorithm 1's step (and Error) vanish.
            result.converged = longest <= TOL1;
            if (result.converged)
              break;
            radius.set(0.25 * radius.value());
            ++result.rejected_steps;
            if (radius.value() < 1e-12 * system.mean_radius())
              break;
            continue;
          }

        // Lines 8-10: take the step; keep it if |F|^2 fell by more than
        // 5 % of the model's prediction.
        auto x = system.coordinates();
        x_old  = x;
        F_old  = F;
        x += s;
        assemble();
        const double actual = 0.5 * (F_old.squaredNorm() - F.squaredNorm()) / c;
        const double rho    = F.allFinite() ? actual / pred : 0.0;
        radius.update(rho, sub.step_norm, sub.on_boundary);
        if (rho > 0.05)
          {
            if (longest < TOL1)
              {
                result.relative_residual = relative_residual(F, result.sums);
                result.converged         = true;
                break;
              }
            continue;
          }
        ++result.rejected_steps;
        system.coordinates() = x_old;
        assemble();
        if (radius.value() < 1e-12 * system.mean_radius())
          break;
      }
    return result;
  }
} // namespace compax::dem

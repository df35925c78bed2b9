#include "dem/solver/lbfgs_relaxation.h"

#include "dem/solver/residual_norms.h"
#include "dem/solver/trust_region_newton.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace compax::dem
{
  namespace
  {
    /// Strong Wolfe curvature parameter: a trial point is accepted once the
    /// directional derivative has dropped to this fraction of its start.
    constexpr double wolfe_curvature = 0.9;
    /// Trial points of one line search before it gives up.
    constexpr int max_trials = 20;
    /// Accepted iterations between refreshes of the preconditioner.
    constexpr int preconditioner_interval = 50;
  } // namespace

  LbfgsRelaxation::LbfgsRelaxation(const int memory)
      : memory(std::max(1, memory))
      , s_history(this->memory)
      , y_history(this->memory)
      , rho(this->memory, 0.0)
      , alpha(this->memory, 0.0)
  {
  }

  void
  LbfgsRelaxation::search_direction()
  {
    d = g;
    for (int k = 0; k < n_stored; ++k)
      {
        const int i = (newest - k + memory) % memory;
        alpha[i]    = rho[i] * s_history[i].dot(d);
        d.noalias() -= alpha[i] * y_history[i];
      }
    d = scaling * d.cwiseProduct(inverse_diagonal);
    for (int k = n_stored - 1; k >= 0; --k)
      {
        const int    i    = (newest - k + memory) % memory;
        const double beta = rho[i] * y_history[i].dot(d);
        d.noalias() += (alpha[i] - beta) * s_history[i];
      }
    d = -d;
  }

  void
  LbfgsRelaxation::remember(const Eigen::VectorXd &s_new,
                            const Eigen::VectorXd &y_new)
  {
    const double sy = s_new.dot(y_new);
    // A pair without positive curvature (a saddle, or a contact list
    // change) would make H indefinite: skip it.
    if (!(sy > 1e-12 * s_new.norm() * y_new.norm()))
      return;
    newest            = (newest + 1) % memory;
    s_history[newest] = s_new;
    y_history[newest] = y_new;
    rho[newest]       = 1.0 / sy;
    n_stored          = std::min(n_stored + 1, memory);
    scaling           = sy / y_new.dot(y_new.cwiseProduct(inverse_diagonal));
  }

  FireResult
  LbfgsRelaxation::relax(EquilibriumSystem &system,
                         const double       target,
                         const int          max_evaluations,
                         const double       force_floor)
  {
    const std::size_t n = system.n_particles();
    inverse_diagonal.resize(3 * n);
    for (int k = 0; k < memory; ++k)
      {
        s_history[k].resize(3 * n);
        y_history[k].resize(3 * n);
      }
    n_stored         = 0;
    newest           = -1;
    scaling          = 1.0;
    const double cap = system.skin();

    start_watching();
    FireResult result;
    assemble_inverse_diagonal(system, g, inverse_diagonal);
    int evaluations = 1, accepted = 0;
    result.assemblies = 1;
    auto x            = system.coordinates();
    for (;;)
      {
        record(result,
               relaxation_balance(g, sums, target, force_floor),
               evaluations);
        if (result.converged || result.stalled
            || evaluations >= max_evaluations)
          break;
        if (accepted > 0 && accepted % preconditioner_interval == 0)
          {
            // The seed of H only: the stored pairs stay valid.
            assemble_inverse_diagonal(system, g, inverse_diagonal);
            ++evaluations;
            ++result.assemblies;
          }
        search_direction();
        double slope0 = g.dot(d);
        if (!(slope0 < 0.0))
          {
            // Not a descent direction: restart from the preconditioned
            // gradient.
            n_stored = 0;
            scaling  = 1.0;
            d        = -g.cwiseProduct(inverse_diagonal);
            slope0   = g.dot(d);
          }
        const double dmax = max_particle_norm(d);
        if (!(dmax > 0.0))
          break;
        const double a_max = cap / dmax;

        // Line search on the directional derivative phi'(a) = g(x0+a d).d.
        x0          = x;
        double a    = std::min(1.0, a_max);
        double a_lo = 0.0, slope_lo = slope0;
        double a_hi = std::numeric_limits<double>::infinity(), slope_hi = 0.0;
        bool   found = false;
        ContactSums trial_sums;
        for (int t = 0; t < max_trials && evaluations < max_evaluations; ++t)
          {
            x          = x0 + a * d;
            trial_sums = system.residual(g_trial);
            ++evaluations;
            const double slope = g_trial.dot(d);
            if (std::abs(slope) <= wolfe_curvature * std::abs(slope0))
              {
                found = true;
                break;
              }
            if (slope < 0.0)
              {
                a_lo     = a;
                slope_lo = slope;
                if (a >= a_max)
                  {
                    found = true; // as far as a particle may move
                    break;
                  }
              }
            else
              {
                a_hi     = a;
                slope_hi = slope;
              }
            if (std::isinf(a_hi))
              a = std::min(2.0 * a, a_max);
            else
              {
                // Secant on phi', safeguarded inside the bracket.
                const double w = a_hi - a_lo;
                a              = a_lo - slope_lo * w / (slope_hi - slope_lo);
                a              = std::clamp(a, a_lo + 0.1 * w, a_hi - 0.1 * w);
              }
          }
        if (!found)
          {
            if (!(a_lo > 0.0))
              {
                x    = x0;
                sums = system.residual(g);
                ++evaluations;
                if (n_stored == 0)
                  break; // not even the preconditioned gradient descends
                n_stored = 0;
                scaling  = 1.0;
                continue;
              }
            // Every point up to a_lo descended: step there.
            a          = a_lo;
            x          = x0 + a * d;
            trial_sums = system.residual(g_trial);
            ++evaluations;
          }
        s.noalias() = a * d;
        y.noalias() = g_trial - g;
        remember(s, y);
        g.swap(g_trial);
        sums = trial_sums;
        ++accepted;
      }
    result.iterations = evaluations;
    result.sums       = sums;
    return result;
  }
} // namespace compax::dem

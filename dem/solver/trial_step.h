#pragma once

#include "dem/solver/equilibrium_system.h"
#include "dem/solver/residual_norms.h"

#include <Eigen/Core>

namespace compax::dem
{
  /**
   * The trial step of a trust-region method on a bed's stored energy
   * (TrustRegionNewton): moves the particles by s and
   * measures the energy change by the trapezoidal rule
   * -(F(x) + F(x+s)).s / 2, exact for a quadratic energy, so that no
   * energy needs to be evaluated. A step that is not kept is undone. The
   * buffers are kept between steps.
   */
  class TrialStep
  {
  public:
    /// Moves `system` by s; `evaluate()` refreshes F at the new point.
    /// Returns the ratio of the actual decrease to `predicted`.
    template <typename Evaluate>
    double
    take(EquilibriumSystem     &system,
         const Eigen::VectorXd &s,
         Eigen::VectorXd       &F,
         const double           predicted,
         Evaluate             &&evaluate)
    {
      auto x = system.coordinates();
      x_old  = x;
      F_old  = F;
      x += s;
      evaluate();
      const double actual = -0.5 * (F_old + F).dot(s);
      return actual / predicted;
    }

    /// Keeps the step s just taken if it achieved more than 5 % of the
    /// predicted decrease (`rho`) at a finite residual; otherwise moves
    /// `system` back and re-evaluates it there (the contact list may have
    /// changed). Returns whether it kept the step.
    template <typename Evaluate>
    bool
    keep_or_undo(const double           rho,
                 const bool             finite,
                 EquilibriumSystem     &system,
                 const Eigen::VectorXd &s,
                 Evaluate             &&evaluate)
    {
      if (rho > 0.05 && finite)
        {
          last_move_ = max_particle_norm(s);
          return true;
        }
      system.coordinates() = x_old;
      evaluate();
      return false;
    }

    /// The largest particle displacement of the last kept step, 0 if none
    /// was kept since forget() [m]: the step part of the convergence test.
    double
    last_move() const
    {
      return last_move_;
    }

    /// No step kept yet (a new solve, or after a relaxation moved the bed).
    void
    forget()
    {
      last_move_ = 0.0;
    }

  private:
    Eigen::VectorXd x_old, F_old;
    double          last_move_ = 0.0;
  };
} // namespace compax::dem

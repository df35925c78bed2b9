#pragma once

#include "dem/solver/equilibrium_system.h"

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  /**
   * The trust radius of a trust-region Newton method on a bed's stored
   * energy (TrustRegionNewton). The radius bounds the
   * M-norm of the whole step; it is set in units of R_mean sqrt(N), so that
   * a radius of r R_mean sqrt(N) lets every particle move by about
   * r R_mean.
   */
  class TrustRadius
  {
  public:
    /// Starts a solve of `system` from the radius the last solve ended
    /// with, or from `initial` if there was none or `restart` asks, kept
    /// within [1e-3 initial, max] (fractions of R_mean sqrt(N)).
    void
    start(const EquilibriumSystem &system,
          const double             initial,
          const double             max,
          const bool               restart = false)
    {
      length_ = system.mean_radius()
                * std::sqrt(static_cast<double>(system.n_particles()));
      initial_ = initial * length_;
      max_     = max * length_;
      if (radius <= 0.0 || restart)
        radius = initial_;
      radius = std::clamp(radius, 1e-3 * initial * length_, max_);
    }

    /// The radius after a trial step of M-norm `step_norm` whose actual
    /// decrease was `rho` times the predicted one: a quarter of the step
    /// where the model predicted poorly, twice the radius (up to the
    /// largest) where it predicted well and the step reached the boundary.
    void
    update(const double rho, const double step_norm, const bool on_boundary)
    {
      if (rho < 0.25)
        radius = 0.25 * step_norm;
      else if (rho > 0.75 && on_boundary)
        radius = std::min(2.0 * radius, max_);
    }

    /// Back to the initial radius (after a FIRE relaxation moved the bed).
    void
    restart()
    {
      radius = initial_;
    }

    /// Forgets the radius, so that the next solve starts from the initial
    /// one (reproducible trials).
    void
    forget()
    {
      radius = -1.0;
    }

    void
    set(const double r)
    {
      radius = r;
    }

    /// The radius [m].
    double
    value() const
    {
      return radius;
    }

    /// R_mean sqrt(N) of the system being solved [m].
    double
    length() const
    {
      return length_;
    }

  private:
    double radius   = -1.0;
    double length_  = 0.0;
    double initial_ = 0.0;
    double max_     = 0.0;
  };
} // namespace compax::dem

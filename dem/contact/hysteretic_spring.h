#pragma once

#include "dem/contact/contact_response.h"

#include <algorithm>
#include <limits>
#include <vector>

/**
 * @file
 * The branches of Luding's hysteretic spring (Luding 2008) in a loading
 * variable x: x = delta for the Walton-Braun spring, x = delta^{3/2} for the
 * multi-contact law of Giannis 2021. Both laws share them; what differs is
 * x, k1 and the terms a law adds.
 */

namespace compax::dem
{
  /// Stiffnesses k1 (loading), k2_max (largest un/reloading) and kc
  /// (adhesion) in units of force per unit of x, and the plastic flow
  /// limit delta* = k2_max/(k2_max - k1) phi_F 2R [m].
  struct HystereticSpring
  {
    double k1     = 0.0;
    double k2_max = 0.0;
    double kc     = 0.0;

    /// delta* [m] for plasticity depth phi_F and effective radius R;
    /// infinite when k2_max = k1.
    double
    plastic_flow_limit(const double phi_F, const double R) const
    {
      if (k2_max == k1)
        return std::numeric_limits<double>::infinity();
      return k2_max / (k2_max - k1) * phi_F * 2.0 * R;
    }

    /// k2(delta_max) = k1 + (k2_max - k1) min(1, delta_max / delta*).
    double
    unloading_stiffness(const double delta_max, const double limit) const
    {
      if (k2_max == k1)
        return k1;
      if (delta_max >= limit)
        return k2_max;
      return k1 + (k2_max - k1) * delta_max / limit;
    }

    /// Force F and dF/dx at x < x_max on the un/reloading branch
    /// k2 (x - x_0), x_0 = (1 - k1/k2) x_max, or the adhesive one -kc x,
    /// whichever is larger.
    void
    unloading_branch(const double x,
                     const double x_max,
                     const double k2,
                     double      &force,
                     double      &slope) const
    {
      const double x0     = (1.0 - k1 / k2) * x_max;
      const double branch = k2 * (x - x0);
      if (branch > -kc * x)
        {
          force = branch;
          slope = k2;
        }
      else
        {
          force = -kc * x;
          slope = -kc;
        }
    }
  };

  /**
   * The one internal variable of a hysteretic spring, the largest overlap
   * delta_max [m], in slot 0 of ContactHistory; the laws built on the
   * spring derive from this to read and write it by name.
   */
  struct LargestOverlapHistory
  {
    static constexpr std::size_t delta_max_slot = 0;

    /// delta_max [m] of a contact's history.
    static double
    delta_max(const ContactHistory &history)
    {
      return history[delta_max_slot];
    }

    /// The history of largest overlap delta_max [m].
    static ContactHistory
    history(const double delta_max)
    {
      ContactHistory h;
      h[delta_max_slot] = delta_max;
      return h;
    }

    /// The history after a converged state at overlap gamma [m]: delta_max
    /// raised to gamma.
    static ContactHistory
    with_largest_overlap(const ContactHistory &history, const double gamma)
    {
      ContactHistory next  = history;
      next[delta_max_slot] = std::max(delta_max(history), gamma);
      return next;
    }

    /// The declaration of delta_max for ContactLaw::history_variables().
    static std::vector<HistoryVariable>
    variables()
    {
      return {{"delta_max", "largest_overlap", "m"}};
    }
  };
} // namespace compax::dem

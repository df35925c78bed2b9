#pragma once

#include <algorithm>

namespace compax::dem
{
  /// Limits of advance_in_substeps().
  struct SubstepLimits
  {
    /// Smallest sub-step as a fraction of the step [-].
    double min_fraction = 1.0 / 1024.0;
    /// Growth of the sub-step after a success [-].
    double growth = 1.5;
  };

  /**
   * Drives a load step from 0 to 1 in adaptive sub-steps: tries the
   * sub-step from the fraction `done` already reached to
   * t = min(1, done + fraction) by `try_substep(t)`, which returns whether
   * it succeeded (a failed sub-step must leave the state as it found it).
   * After a success the sub-step grows by `limits.growth` (up to the whole
   * step); after a failure it is halved, down to `limits.min_fraction`, and a
   * failure of the smallest sub-step ends the step. `fraction` carries the
   * sub-step over from one step to the next; `cutbacks` counts the failures.
   * Returns whether the step was completed.
   */
  template <typename TrySubstep>
  bool
  advance_in_substeps(double              &fraction,
                      const SubstepLimits &limits,
                      int                 &cutbacks,
                      TrySubstep         &&try_substep)
  {
    const double min_fraction = limits.min_fraction;
    const double growth       = limits.growth;
    double       done         = 0.0;
    fraction                  = std::clamp(fraction, min_fraction, 1.0);
    while (done < 1.0)
      {
        const double t = std::min(1.0, done + fraction);
        if (try_substep(t))
          {
            done     = t;
            fraction = std::min(1.0, fraction * growth);
            continue;
          }
        ++cutbacks;
        if (fraction <= min_fraction * (1.0 + 1e-12))
          return false;
        fraction = std::max(0.5 * fraction, min_fraction);
      }
    return true;
  }
} // namespace compax::dem

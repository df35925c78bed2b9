#pragma once

#include "dem/solver/equilibrium_system.h"

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>

namespace compax::dem
{
  /// Mean of the positive overlaps (contacts in compression) [m], or
  /// `fallback` if none: the overlap a closing contact may reach within one
  /// solver step (the force scale the quadratic model already knows).
  class MeanOverlap
  {
  public:
    void
    add(const double gamma)
    {
      if (gamma > 0.0)
        {
          sum += gamma;
          ++n;
        }
    }

    double
    value(const double fallback) const
    {
      return n > 0 ? sum / n : fallback;
    }

  private:
    double      sum = 0.0;
    std::size_t n   = 0;
  };

  /// factor[i] = min(factor[i], (gap + allowance) / closing) when the
  /// particle's step closes a gap by more than gap + allowance; returns
  /// whether it did.
  inline bool
  limit_step_to_gap(Eigen::VectorXd  &factor,
                    const std::size_t i,
                    const double      gap,
                    const double      closing,
                    const double      allowance)
  {
    if (closing <= gap + allowance)
      return false;
    factor[i] = std::min(factor[i], (gap + allowance) / closing);
    return true;
  }

  /**
   * Shortens the step s particle by particle, so that no particle closes a
   * gap the quadratic model does not see (EquilibriumSystem::limit_closing)
   * and none moves farther than a quarter of the Verlet skin (the contact
   * list stays valid). Capping the few particles that would, instead of
   * shrinking the trust region of the whole bed, keeps the others' steps.
   * `factor` receives each particle's scale; returns whether s changed.
   */
  bool
  limit_step_to_gaps(const EquilibriumSystem &system,
                     Eigen::VectorXd         &s,
                     Eigen::VectorXd         &factor);
} // namespace compax::dem

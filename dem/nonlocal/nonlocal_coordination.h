#pragma once

#include "dem/nonlocal/nonlocal_bed_system.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// Mechanical coordination number 2 (loaded particle pairs) / N of the
  /// system at its current state (evaluates its residual) [-].
  inline double
  coordination_number(NonlocalBedSystem &system)
  {
    Eigen::VectorXd F;
    system.residual(F);
    const std::size_t n = system.n_particles();
    return n > 0 ? 2.0 * static_cast<double>(system.n_loaded_pairs())
                     / static_cast<double>(n)
                 : 0.0;
  }
} // namespace compax::dem

#pragma once

#include "dem/walls/die_walls.h"

#include <cstddef>

namespace compax::dem
{
  /// Force sums gathered while assembling a residual.
  struct ContactSums
  {
    /// Sum of the normal forces P on each wall [N] (positive compressive):
    /// index Wall::lower_punch, upper_punch, die (zero without walls).
    double wall_force[n_walls] = {0.0, 0.0, 0.0};
    /// Mean |P| over contacts carrying a non-zero force [N].
    double mean_force = 0.0;
    /// Number of contacts with non-zero force.
    std::size_t n_loaded = 0;
  };
} // namespace compax::dem

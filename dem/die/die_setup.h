#pragma once

#include "dem/packing/ballistic_deposition.h"
#include "dem/solver/bed.h"

namespace compax::dem
{
  /**
   * A bed filled into a die by ballistic deposition: lower punch at z = 0,
   * upper punch touching the highest sphere, Verlet skin `skin_fraction`
   * times the mean radius.
   */
  Bed
  fill_die(const DepositionParameters &deposition, double skin_fraction = 0.3);

  /// Evenly spaced targets from rho_start (excluded) to rho_end
  /// (included) [-].
  std::vector<double>
  density_targets(double rho_start, double rho_end, int n_steps);
} // namespace compax::dem

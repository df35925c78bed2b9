#pragma once

#include "dem/analysis/curve_fits.h"

#include <optional>
#include <vector>

/**
 * @file
 * Where a compaction jams, measured the same way for the die and the
 * periodic cell: Eq. (14) of Gonzalez 2018 fitted to the jammed states.
 */

namespace compax::dem
{
  /// One converged state of a uniaxial compaction.
  struct CompactionState
  {
    double relative_density = 0.0;
    /// Axial compressive stress [Pa]: the die's upper punch pressure, the
    /// cell's -sigma_zz.
    double axial_pressure = 0.0;
    /// Coordination number (contacts carrying a resolved force) [-].
    double coordination_number = 0.0;
  };

  /// The jammed ones of @p states: axial pressure above
  /// @p pressure_resolution [Pa] and a positive Z.
  std::vector<CompactionState>
  jammed_states(const std::vector<CompactionState> &states,
                double                              pressure_resolution);

  /**
   * Eq. (14), Z = Z_c + Z_0 (rho - rho_c_Z)^theta, fitted to the
   * jammed_states() (below the resolution the bed carries nothing the
   * contact law resolves). Empty with fewer than five jammed states, when the
   * fit fails, when its optimum stands on the edge of the searched range
   * (CoordinationFit::on_search_edge: no state near the onset, as after a
   * consolidation that jumps from a loose bed to a loaded one), or when its
   * Z_c is negative (no coordination number: the power law then fits a
   * path that rises from a state far below its own onset).
   */
  std::optional<CoordinationFit>
  fit_jamming(const std::vector<CompactionState> &states,
              double                              pressure_resolution);
} // namespace compax::dem

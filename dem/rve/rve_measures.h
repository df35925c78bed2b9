#pragma once

#include "dem/rve/periodic_bed.h"

#include <cstddef>

namespace compax::dem
{
  /// Microstructure measures of an equilibrated periodic cell.
  struct RveMeasures
  {
    /// 2 x (contacts carrying a non-zero force) / N, the die's definition
    /// (every particle counted) [-]. A pair touching through two images
    /// counts twice.
    double coordination_number = 0.0;
    /// The same over the mechanically stable backbone: rattlers (particles
    /// with fewer than 4 loaded contacts, removed repeatedly since removing
    /// one unloads its neighbours) left out [-].
    double coordination_without_rattlers = 0.0;
    /// Rattlers / N [-].
    double rattler_fraction = 0.0;
    /// A_b = sum a_p^2 / sum R_i^2 over the pairs that touch (Gonzalez
    /// 2018 Sec. 5.6, the die's definition, BedMeasures) [-].
    double bonding_surface = 0.0;
    /// Contacts with an intact solid bridge (a_B > 0).
    std::size_t n_bonds = 0;
  };

  RveMeasures
  measure_rve(const PeriodicBed &bed);
} // namespace compax::dem

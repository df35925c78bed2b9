#pragma once

#include "dem/packing/random_source.h"
#include "dem/rve/periodic_bed.h"

#include <cstddef>
#include <cstdint>

namespace compax::dem
{
  /// A periodic cell cut from a ballistic deposit (see
  /// make_deposited_packing()).
  struct DepositedPackingSpec
  {
    /// Spheres in the cell (exactly).
    std::size_t particle_count = 200;
    /// Radii (monodisperse or log-normal with cut-offs).
    SizeDistribution sizes;
    /// Deposit left out below and above the cell, in mean diameters [-]:
    /// the layers ordered by the flat floor and the loose top surface.
    double margin_diameters = 3.0;
    /// Verlet skin as a fraction of the mean radius [-].
    double        skin = 0.3;
    std::uint64_t seed = 1;
    /// Material of every particle (an index of the ContactModel).
    unsigned int material = 0;
  };

  /**
   * The RVE counterpart of the die's loose bed (Gonzalez 2018, Sec. 5): a
   * fully periodic cell whose spheres come from a ballistic deposition
   * (Jullien & Meakin 1989, the die's packing algorithm) into a square
   * column periodic in x and y, so that its contact network has the
   * deposit's structure: loose, touching without force, ordered by the
   * direction of deposition (z, the compaction axis of a die). The cell is
   * the deposit's core: the spheres whose centres lie above
   * margin_diameters mean diameters, the particle_count lowest of them;
   * its height is the midpoint to the next sphere, raised where a sphere
   * at the top would overlap the periodic image of one at the bottom, so
   * that no two spheres overlap across the new periodic face. The column's
   * side is chosen for a cubic cell; the deposit is grown until its core
   * holds the spheres. The spheres are virgin (no history) and touch; the
   * density is the deposit's core density (0.48-0.53 measured for 80 to
   * 1000 equal spheres). Reproducible: the same spec gives the same cell.
   */
  PeriodicBed
  make_deposited_packing(const DepositedPackingSpec &spec);
} // namespace compax::dem

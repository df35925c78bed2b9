#pragma once

#include "dem/packing/random_source.h"
#include "dem/particles/particle_system.h"

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /// Parameters of a ballistic deposition into a square die.
  struct SquareDepositionParameters
  {
    /// Side L of the square cross-section, centred on the z axis [m].
    double width = 1e-3;
    /// Size distribution of each material.
    std::vector<SizeDistribution> sizes;
    /// Number of particles of each material (same length as sizes); they
    /// are dropped in a random order.
    std::vector<std::size_t> counts;
    std::uint64_t            seed = 1;
  };

  /**
   * Ballistic deposition after Jullien & Meakin (1989) into a die of square
   * cross-section with its floor at z = 0: each sphere is dropped at a
   * uniformly random horizontal position, falls until it touches the floor
   * or a sphere already placed, then rolls down over its supports by
   * projected descent (move down by h, project out of every overlap with
   * the spheres, the floor and the four walls, accept if it went down,
   * halve h otherwise) until h < 1e-6 R. Neighbours are found in columns of
   * cells of size 2 R_max, so the cost is O(N) for a bounded radius ratio.
   * Deterministic for a given seed.
   */
  ParticleSystem
  square_die_deposition(const SquareDepositionParameters &parameters);
} // namespace compax::dem

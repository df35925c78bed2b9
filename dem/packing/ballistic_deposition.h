#pragma once

#include "dem/packing/deposition_column.h"
#include "dem/packing/random_source.h"
#include "dem/particles/particle_system.h"

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /// Parameters of a ballistic deposition into a die (floor at z = 0).
  struct DepositionParameters
  {
    std::size_t n_particles = 500;
    /// Die diameter D, or side L of a periodic column or square die [m].
    double              die_diameter = 4e-3;
    DepositionContainer container    = DepositionContainer::cylinder;
    SizeDistribution    sizes;
    /// Probability of each material (normalized); empty = all material 0.
    std::vector<double> material_fractions;
    std::uint64_t       seed = 1;
  };

  /**
   * Ballistic deposition after Jullien & Meakin (1989): spheres are
   * dropped one at a time at uniformly random horizontal positions inside
   * the die, fall until they touch the floor or a sphere already placed,
   * then roll down over their supports until they rest stably (a local
   * minimum of height on the floor, in a pocket of three supports, or
   * against the die wall; a periodic column wraps around in x and y
   * instead). The rolling is a projected descent: move down
   * by h, project out of every overlap (with spheres, floor and die wall),
   * accept if the sphere went down, halve h otherwise, until h < 1e-6 R.
   * Deterministic for a given seed (see RandomSource).
   */
  ParticleSystem
  ballistic_deposition(const DepositionParameters &parameters);
} // namespace compax::dem

#pragma once

#include "dem/particles/particle_system.h"
#include "dem/solver/contact_set.h"
#include "dem/walls/die_walls.h"

namespace compax::dem
{
  /**
   * Everything that defines a state of a bed in a die: particle positions,
   * wall positions and the contacts with their internal variables. Copying
   * a Bed saves a state (the die protocol branches from saved states).
   */
  struct Bed
  {
    ParticleSystem particles;
    DieWalls       walls;
    ContactSet     contacts;

    /// In-die relative density: solid volume / pi D^2 H / 4 [-].
    double
    relative_density() const
    {
      return particles.solid_volume() / walls.enclosed_volume();
    }
  };

  /// Branch vector d = x_i - x_j of a pair contact [m]; the normal
  /// n = d/|d| points from j to i.
  inline Eigen::Vector3d
  branch_vector(const Bed &bed, const PairContact &c)
  {
    return bed.particles.positions[c.i] - bed.particles.positions[c.j];
  }
} // namespace compax::dem

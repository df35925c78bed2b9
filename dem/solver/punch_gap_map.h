#pragma once

#include "dem/particles/particle_system.h"
#include "dem/walls/die_walls.h"

namespace compax::dem
{
  /// Which particles map_heights() moves.
  enum class GapParticles
  {
    /// Every particle.
    all,
    /// Only those between the punches of `from`.
    between_punches
  };

  /**
   * Maps particle heights affinely from the punch gap of `from` onto that
   * of `to`, the predictor of a load step that has no converged increment
   * to scale (consolidation, a reversal of the punch direction).
   */
  inline void
  map_heights(ParticleSystem    &p,
              const DieWalls    &from,
              const DieWalls    &to,
              const GapParticles which)
  {
    const double h0 = from.height(), h1 = to.height();
    if (h0 <= 0.0 || h1 == h0)
      return;
    for (auto &x : p.positions)
      {
        const double t = (x[2] - from.lower_punch) / h0;
        if (which == GapParticles::all || (t >= 0.0 && t <= 1.0))
          x[2] = to.lower_punch + t * h1;
      }
  }
} // namespace compax::dem

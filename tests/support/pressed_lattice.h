#pragma once

#include "dem/solver/bed.h"

#include <random>

namespace compax::testing
{
  /**
   * A side^3 simple cubic lattice of spheres of radius about R (+-2 %) at
   * spacing 2 R * 0.97, jittered by +-1 % of R: every face neighbour
   * overlaps, none else. Between the punches of a die wide enough that no
   * sphere touches its wall; contact list built with a skin of R / 2.
   * Large enough (side 24) for the threaded residual.
   */
  inline dem::Bed
  pressed_lattice(const dem::ContactModel &model,
                  const double             R,
                  const int                side)
  {
    const double a = 2 * R * 0.97;
    dem::Bed     bed;
    bed.walls.diameter    = 2 * side * a;
    bed.walls.lower_punch = 0.0;
    bed.walls.upper_punch = side * a + R;
    bed.contacts.set_skin(0.5 * R);
    std::mt19937_64 rng(7);
    auto            u = [&]() { return (rng() >> 11) * 0x1.0p-53 - 0.5; };
    for (int k = 0; k < side; ++k)
      for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
          {
            Eigen::Vector3d x((i - side / 2) * a,
                              (j - side / 2) * a,
                              R + k * a);
            x += 0.02 * R * Eigen::Vector3d(u(), u(), u());
            bed.particles.add(x, R * (1.0 + 0.04 * u()));
          }
    bed.contacts.rebuild(bed.particles, bed.walls, model);
    return bed;
  }
} // namespace compax::testing

#pragma once

#include "dem/solver/bed.h"

#include <cstddef>

namespace compax::dem
{
  /**
   * Stress and solid fraction of the interior of a die compact: the
   * particles whose centres lie farther than a given distance from the die
   * wall and from both punches. The wall layer of a die is looser and
   * loaded differently (ordering against the flat walls, wall friction), so
   * the interior, not the die average, is what a periodic RVE represents
   * (issue #15, item 4).
   *
   * The region is the cylinder r < D/2 - w, z_lower + w < z < z_upper - w
   * for wall distance w, of volume V = pi (D/2 - w)^2 (H - 2 w). Solid
   * fraction = sum of the volumes of the spheres whose centres lie in it /
   * V. Stress: the Love-Weber (Christoffersen) average over the same
   * particles, sigma = (1/V) sum_i sum_c (x_c - x_i) (x) f_c, with f_c the
   * force on particle i at its contact point x_c (tension positive); both
   * sums count every sphere whose centre is inside, so they err by the same
   * boundary layer of one radius. sigma_rr projects each particle's tensor
   * on its own radial direction e_r (axisymmetric mean; a particle on the
   * axis contributes (sigma_xx + sigma_yy)/2).
   */
  struct InteriorMeasures
  {
    /// Spheres whose centres lie in the interior region [-] (0: the region
    /// is empty, every other member is NaN).
    std::size_t particles = 0;
    /// Solid fraction of the interior region [-].
    double relative_density;
    /// Axial and radial Love-Weber stress of the region, tension positive
    /// [Pa].
    double sigma_zz;
    double sigma_rr;
  };

  /// The interior of @p bed: the particles farther than @p wall_distance
  /// [m] from the die wall and from both punches (see InteriorMeasures).
  /// @p resolution [N] as in measure(): forces below it count as zero. A
  /// region lower or narrower than @p min_extent [m] gives no numbers
  /// (particles = 0): counting whole spheres by their centres, a region a
  /// few layers thick reads the layering of the walls, not the compact
  /// (solid fractions above 1 in a region thinner than a diameter).
  InteriorMeasures
  measure_interior(const Bed &bed,
                   double     wall_distance,
                   double     resolution = 0.0,
                   double     min_extent = 0.0);
} // namespace compax::dem

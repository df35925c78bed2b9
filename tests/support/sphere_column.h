#pragma once

#include "dem/solver/bed.h"

#include <Eigen/Core>

namespace compax::testing
{
  /// Where the rattler of sphere_column() sits, for spheres of radius
  /// @p R: away from the column.
  inline Eigen::Vector3d
  column_rattler(const double R)
  {
    return {4 * R, 0.0, 3 * R};
  }

  /**
   * N spheres of radius @p R in a simple-cubic column between the punches,
   * touching, with the upper punch lowered by @p squeeze (so that all of
   * it sits in the top contact), and a rattler at column_rattler(R).
   */
  inline dem::Bed
  sphere_column(const int N, const double R, const double squeeze)
  {
    dem::Bed bed;
    bed.walls.diameter    = 12 * R;
    bed.walls.upper_punch = 2 * R * N - squeeze;
    bed.contacts.set_skin(0.3 * R);
    for (int k = 0; k < N; ++k)
      bed.particles.add({0.0, 0.0, R + 2 * R * k}, R);
    bed.particles.add(column_rattler(R), R);
    return bed;
  }
} // namespace compax::testing

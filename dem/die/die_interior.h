#pragma once

#include "dem/solver/bed.h"

#include <Eigen/Core>

#include <cstddef>

namespace compax::dem
{
  /**
   * How the region's solid fraction and stress count a sphere that the
   * region's boundary cuts.
   */
  enum class InteriorWeighting
  {
    /**
     * Each sphere by the part of its volume inside the region (exact up to
     * the quadrature of the cut by the cylinder, see
     * volume_in_die_region()): unbiased where the walls order the spheres
     * in layers, whose centres a boundary at a fixed distance from a wall
     * otherwise cuts unevenly (+0.018 in solid fraction at die density
     * 0.70 in the 6512-sphere die with centres; doc/loose_regime.md).
     */
    volume_fraction,
    /// Each sphere whose centre lies inside, whole; the rest not at all.
    sphere_centres
  };

  /**
   * Stress and solid fraction of the interior of a die compact: the
   * region farther than a given distance from the die wall and from both
   * punches. The wall layer of a die is looser and loaded differently
   * (ordering against the flat walls, wall friction), so the interior, not
   * the die average, is what a periodic RVE represents (issue #15, item 4).
   *
   * The region is the cylinder r < D/2 - w, z_lower + w < z < z_upper - w
   * for wall distance w, of volume V = pi (D/2 - w)^2 (H - 2 w). With
   * weights v_i, the part of sphere i counted (InteriorWeighting):
   * solid fraction = sum_i v_i V_i / V, and the Love-Weber
   * (Christoffersen) stress sigma = (1/V) sum_i v_i sum_c (x_c - x_i) (x)
   * f_c, with f_c the force on particle i at its contact point x_c
   * (tension positive): the region's volume average of each particle's
   * mean stress. sigma_rr projects each particle's tensor on its own
   * radial direction e_r (axisymmetric mean; a particle on the axis
   * contributes (sigma_xx + sigma_yy)/2).
   */
  struct InteriorMeasures
  {
    /// Spheres counted with a positive weight [-] (0: the region holds
    /// none, every other member is NaN).
    std::size_t particles = 0;
    /// Solid fraction of the interior region [-].
    double relative_density;
    /// Axial and radial Love-Weber stress of the region, tension positive
    /// [Pa].
    double sigma_zz;
    double sigma_rr;
    /// Mean number of contacts carrying a resolved force per sphere, each
    /// sphere weighted as in the solid fraction [-].
    double coordination_number;
  };

  /// The interior of @p bed: the region farther than @p wall_distance [m]
  /// from the die wall and from both punches (see InteriorMeasures).
  /// @p resolution [N] as in measure(): forces below it count as zero. A
  /// region lower or narrower than @p min_extent [m] gives no numbers
  /// (particles = 0): a region a few layers thick reads the layering of
  /// the walls, not the compact (with sphere_centres, solid fractions
  /// above 1 in a region thinner than a diameter).
  InteriorMeasures
  measure_interior(const Bed        &bed,
                   double            wall_distance,
                   double            resolution = 0.0,
                   double            min_extent = 0.0,
                   InteriorWeighting weighting
                   = InteriorWeighting::volume_fraction);

  /**
   * Volume [m^3] of the sphere of centre @p x and radius @p R inside the
   * cylinder r < @p r_max (axis z through the origin),
   * @p z_lower < z < @p z_upper: the integral over the sphere's horizontal
   * slices of their overlap with the disc r < r_max (the lens of two
   * circles), in closed form where no slice is cut and by 25-point
   * Gauss-Legendre quadrature where the cylinder cuts the sphere.
   */
  double
  volume_in_die_region(const Eigen::Vector3d &x,
                       double                 R,
                       double                 r_max,
                       double                 z_lower,
                       double                 z_upper);
} // namespace compax::dem

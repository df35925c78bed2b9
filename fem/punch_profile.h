#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace compax::fem
{
  /// Where a body point stands relative to a rigid punch face.
  template <int dim>
  struct PunchGap
  {
    /// Signed distance to the face [m]: positive open, negative overlap.
    double gap = 0.0;
    /// Unit normal of the face at the nearest point, pointing out of the
    /// body into the punch.
    dealii::Tensor<1, dim> normal;
    /// Curvature 1/rho of the face there [1/m]: the normal turns by
    /// (I - n n) du / rho when the point moves by du (0 on a flat face).
    double curvature = 0.0;
  };

  /**
   * Face of the upper punch: flat, or a concave spherical cup of depth h_c
   * and radius of curvature R_c (the usual "standard concave" tooling) with
   * a flat land from the cup edge r = a = sqrt(2 R_c h_c - h_c^2) to the
   * die wall. The powder fills the cup, so a compact under it is h_c
   * thicker on the axis than at the die wall. Heights are measured from
   * the land, which is where the punch "position" of the solver is.
   *
   * Near the cup edge the punch is the intersection of the region outside
   * the cup sphere and the half space above the land, so the penetration
   * of a point is the smaller of its penetrations of the two, i.e. the gap
   * is the larger of the two signed distances (exact wherever a point
   * overlaps the punch).
   */
  struct PunchProfile
  {
    /// Cup depth h_c [m]; 0: flat face.
    double cup_depth = 0.0;
    /// Radius of curvature R_c of the cup [m] (used when cup_depth > 0).
    double cup_radius = 0.0;

    bool
    is_flat() const
    {
      return cup_depth == 0.0;
    }

    /// Radius a of the cup's edge on the land [m] (0 for a flat face).
    double
    cup_edge_radius() const;

    /// Height of the face above the land at radius @p r [m].
    double
    height(double r) const;

    /// Volume between the cup and the plane of the land [m^3]: the
    /// spherical cap pi h_c^2 (3 R_c - h_c) / 3.
    double
    cup_volume() const;

    /// Throws std::invalid_argument unless 0 <= h_c <= R_c and the cup fits
    /// in a die of radius @p die_radius (a <= die_radius).
    void
    validate(double die_radius) const;

    /**
     * Gap of the point @p x (r-z coordinates in 2-D; the axis is z in 3-D)
     * to this face with its land at height @p land.
     */
    template <int dim>
    PunchGap<dim>
    gap(const dealii::Point<dim> &x, double land) const;
  };
} // namespace compax::fem

#include "fem/punch_profile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace compax::fem
{
  double
  PunchProfile::cup_edge_radius() const
  {
    if (is_flat())
      return 0.0;
    return std::sqrt(std::max(0.0, cup_depth * (2.0 * cup_radius - cup_depth)));
  }

  double
  PunchProfile::height(const double r) const
  {
    if (is_flat() || r >= cup_edge_radius())
      return 0.0;
    // h_c - R_c + sqrt(R_c^2 - r^2), without cancellation for R_c >> r.
    return cup_depth
           - r * r / (cup_radius + std::sqrt(cup_radius * cup_radius - r * r));
  }

  double
  PunchProfile::cup_volume() const
  {
    const double pi = 3.14159265358979323846;
    return pi * cup_depth * cup_depth * (3.0 * cup_radius - cup_depth) / 3.0;
  }

  void
  PunchProfile::validate(const double die_radius) const
  {
    if (!(cup_depth >= 0.0))
      throw std::invalid_argument("punch profile: cup depth must be >= 0");
    if (is_flat())
      return;
    if (!(cup_radius >= cup_depth))
      throw std::invalid_argument(
        "punch profile: the cup radius of curvature must be at least the cup "
        "depth (no undercut cups)");
    if (cup_edge_radius() > die_radius * (1.0 + 1e-12))
      throw std::invalid_argument(
        "punch profile: the cup (edge radius sqrt(2 R_c h_c - h_c^2) = "
        + std::to_string(cup_edge_radius())
        + " m) is wider than the die (radius " + std::to_string(die_radius)
        + " m)");
  }

  template <int dim>
  PunchGap<dim>
  PunchProfile::gap(const dealii::Point<dim> &x, const double land) const
  {
    PunchGap<dim> land_gap;
    land_gap.gap             = land - x[dim - 1];
    land_gap.normal[dim - 1] = 1.0;
    if (is_flat())
      return land_gap;
    // Distance rho from the centre of the cup sphere, on the axis at
    // land + h_c - R_c. A shallow cup has R_c >> rho - R_c, so R_c - rho is
    // formed from R_c^2 - rho^2 = -(r^2 + w^2 + 2 w R_c), w = z - land - h_c,
    // without cancellation.
    const double           w = x[dim - 1] - land - cup_depth;
    dealii::Tensor<1, dim> d;
    double                 r2 = 0.0;
    for (int k = 0; k < dim - 1; ++k)
      {
        d[k] = x[k];
        r2 += x[k] * x[k];
      }
    d[dim - 1]       = w + cup_radius;
    const double rho = d.norm();
    const double g = -(r2 + w * w + 2.0 * w * cup_radius) / (cup_radius + rho);
    if (!(g > land_gap.gap) || rho == 0.0)
      return land_gap;
    PunchGap<dim> cup;
    cup.gap       = g;
    cup.normal    = d / rho;
    cup.curvature = 1.0 / rho;
    return cup;
  }

  template PunchGap<2>
  PunchProfile::gap(const dealii::Point<2> &, double) const;
  template PunchGap<3>
  PunchProfile::gap(const dealii::Point<3> &, double) const;
} // namespace compax::fem

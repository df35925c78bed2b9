#pragma once

#include <Eigen/Core>

namespace compax::dem
{
  /// The rigid walls of a die: punch faces normal to z, and the die wall.
  enum class Wall : int
  {
    lower_punch = 0,
    upper_punch = 1,
    die         = 2
  };

  inline constexpr int n_walls = 3;

  /**
   * Geometry of a sphere touching a rigid wall: the overlap gamma (positive
   * in compression), the unit normal along which the wall pushes the
   * sphere, and the curvature term of the die wall.
   */
  struct WallGap
  {
    double          overlap = 0.0;
    Eigen::Vector3d normal  = Eigen::Vector3d::Zero();
    /// Distance of the centre from the die axis r [m] (die wall only); the
    /// normal turns with the centre, which gives the geometric stiffness
    /// P / r (I - e_r e_r^T) in the horizontal plane.
    double axis_distance = 0.0;
  };

  /**
   * A cylindrical die of diameter D with axis z through the origin, closed
   * by two flat punches at heights z_lower < z_upper. The die wall can be
   * removed (ejection) or its radius changed.
   */
  struct DieWalls
  {
    /// Die diameter D [m].
    double diameter = 0.0;
    /// Height of the lower punch face [m].
    double lower_punch = 0.0;
    /// Height of the upper punch face [m].
    double upper_punch = 0.0;
    /// Whether the die wall constrains the particles.
    bool die_present = true;

    double
    radius() const
    {
      return 0.5 * diameter;
    }

    /// Punch gap H = z_upper - z_lower [m].
    double
    height() const
    {
      return upper_punch - lower_punch;
    }

    /// Punch face area pi D^2 / 4 [m^2].
    double
    punch_area() const;

    /// Volume enclosed by the punches and the die, pi D^2 H / 4 [m^3].
    double
    enclosed_volume() const;

    /// Die-wall area in contact with the compact, pi D H [m^2].
    double
    wall_area() const;

    /// Overlap and normal of a sphere (centre x, radius R) with a wall.
    WallGap
    gap(Wall wall, const Eigen::Vector3d &x, double R) const;

    /// Position of a wall along its own normal coordinate (z for punches,
    /// radius for the die), used to measure how far it moved.
    double
    coordinate(Wall wall) const;
  };
} // namespace compax::dem

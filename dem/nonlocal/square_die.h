#pragma once

#include <Eigen/Core>

#include <array>

namespace compax::dem
{
  /**
   * The six rigid flat walls of a die with a square cross-section (Gonzalez
   * & Cuitino 2012, Sec. 4.2): four die walls x, y = -+L/2 and two punch
   * faces z = z_lower, z_upper. Frictionless, so each wall only pushes
   * along its own normal and, being flat, adds no geometric stiffness.
   */
  struct SquareDie
  {
    /// The walls; indices into wall_force arrays.
    enum Face : int
    {
      lower_punch = 0,
      upper_punch = 1,
      x_lower     = 2,
      x_upper     = 3,
      y_lower     = 4,
      y_upper     = 5
    };
    static constexpr int n_faces = 6;

    /// Side L of the square cross-section, centred on the z axis [m].
    double width = 1e-3;
    /// Heights of the punch faces [m].
    double lower_punch_height = 0.0;
    double upper_punch_height = 1e-3;

    /// Punch gap H [m].
    double
    height() const
    {
      return upper_punch_height - lower_punch_height;
    }

    /// Enclosed volume L^2 H [m^3].
    double
    enclosed_volume() const
    {
      return width * width * height();
    }

    /// Unit normal pointing from the inside of the die into the wall.
    static Eigen::Vector3d
    outward_normal(int face);

    /// Distance from x to the plane of the wall, positive inside the die [m].
    double
    distance(int face, const Eigen::Vector3d &x) const;

    /// Position of the plane along its outward normal [m].
    double
    plane(int face) const;

    /// Name used in tables, e.g. "x_lower".
    static const char *
    face_name(int face);
  };
} // namespace compax::dem

#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include <array>
#include <cstdint>

namespace compax::dem
{
  /// Integer lattice translation n of a periodic image, x + H n.
  using LatticeImage = std::array<std::int32_t, 3>;

  /**
   * A parallelepiped cell x = H s, s in [0, 1)^3, spanned by the columns of
   * the lattice matrix H, periodic along any subset of its three lattice
   * directions. The uniaxial compaction cell is an orthogonal box periodic
   * in x and y with plates closing z; the fully periodic RVE under a
   * deformation gradient F uses the same class with set_lattice(F H_0).
   *
   * Positions are kept unwrapped by the dynamics (a pair stores the image
   * that joins its two unwrapped positions, which stays valid however far
   * the particles travel); wrap() maps them into the cell for output and
   * binning.
   */
  class PeriodicCell
  {
  public:
    /// @param lattice H, columns a_1, a_2, a_3 [m], origin at 0
    /// @param periodic which lattice directions are periodic
    PeriodicCell(const Eigen::Matrix3d &lattice, std::array<bool, 3> periodic);

    /// Orthogonal box [0, L_x) x [0, L_y) x [0, L_z).
    static PeriodicCell
    box(const Eigen::Vector3d &lengths, std::array<bool, 3> periodic);

    /// New lattice (e.g. F H_0 for a deformed RVE); keeps the periodicity.
    void
    set_lattice(const Eigen::Matrix3d &lattice);

    const Eigen::Matrix3d &
    lattice() const
    {
      return H;
    }

    const Eigen::Matrix3d &
    inverse_lattice() const
    {
      return H_inv;
    }

    bool
    periodic(int axis) const
    {
      return is_periodic[axis];
    }

    /// Fractional coordinates s = H^{-1} x.
    Eigen::Vector3d
    fractional(const Eigen::Vector3d &x) const
    {
      return H_inv * x;
    }

    /// Translation H n of image n; non-periodic components of n are ignored.
    Eigen::Vector3d
    image_offset(const LatticeImage &n) const;

    /// Maps x into the cell along the periodic directions (s_d in [0, 1))
    /// and returns the image n with x_old = x_new + H n.
    LatticeImage
    wrap(Eigen::Vector3d &x) const;

    /**
     * The shortest periodic image of a separation d, by rounding its
     * fractional coordinates. Exact when |d| is below half the smallest
     * perpendicular width of a not too skewed cell, which is all a contact
     * search needs.
     */
    Eigen::Vector3d
    minimum_image(const Eigen::Vector3d &d) const;

    /// Distance between the two faces normal to lattice direction axis,
    /// V / |a_j x a_k| [m].
    double
    width(int axis) const;

    /// |det H| [m^3].
    double
    volume() const;

  private:
    Eigen::Matrix3d     H;
    Eigen::Matrix3d     H_inv;
    std::array<bool, 3> is_periodic;
  };
} // namespace compax::dem

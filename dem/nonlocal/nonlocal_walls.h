#pragma once

#include "dem/nonlocal/square_die.h"
#include "dem/walls/die_walls.h"

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace compax::dem
{
  /**
   * The rigid frictionless walls a NonlocalBedSystem confines its spheres
   * with. Each wall w has a distance d_w(x) from a sphere centre x,
   * positive inside, and the outward unit normal n_w(x) = -grad d_w (from
   * the centre towards the contact point), so that the overlap
   * gamma = R - d_w(x) has d gamma / dx = n_w(x). Flat walls have a
   * constant normal; a curved wall's normal turns with the centre,
   * dn = (d n_w / dx) v, which gives the geometric stiffness P dn.
   */
  class NonlocalWalls
  {
  public:
    /// Walls are numbered 0 .. n_walls() - 1 (at most max_walls).
    static constexpr int max_walls = 6;

    virtual ~NonlocalWalls() = default;

    virtual int
    n_walls() const = 0;

    /// d_w(x) [m]; +infinity for a wall that is absent.
    virtual double
    distance(int wall, const Eigen::Vector3d &x) const = 0;

    virtual Eigen::Vector3d
    outward_normal(int wall, const Eigen::Vector3d &x) const = 0;

    /// (d n_w / dx) v at x [1/m times the unit of v].
    virtual Eigen::Vector3d
    normal_derivative(int                    wall,
                      const Eigen::Vector3d &x,
                      const Eigen::Vector3d &v) const = 0;

    /// A number that changes whenever the wall moves (rebuilds the
    /// candidate list).
    virtual double
    position(int wall) const = 0;

    /// Slot of ContactSums::wall_force the wall's force is added to
    /// (lower punch, upper punch, lateral walls).
    virtual int
    sums_slot(int wall) const = 0;
  };

  /// Flat walls: constant normals, which add no geometric stiffness.
  class FlatWalls : public NonlocalWalls
  {
  public:
    Eigen::Vector3d
    normal_derivative(int,
                      const Eigen::Vector3d &,
                      const Eigen::Vector3d &) const final
    {
      return Eigen::Vector3d::Zero();
    }
  };

  /// The six flat walls of a SquareDie (numbered by SquareDie::Face).
  class SquareDieWalls final : public FlatWalls
  {
  public:
    explicit SquareDieWalls(const SquareDie &die)
        : die(die)
    {
    }

    int
    n_walls() const override
    {
      return SquareDie::n_faces;
    }

    double
    distance(const int wall, const Eigen::Vector3d &x) const override
    {
      return die.distance(wall, x);
    }

    Eigen::Vector3d
    outward_normal(const int wall, const Eigen::Vector3d &) const override
    {
      return SquareDie::outward_normal(wall);
    }

    double
    position(const int wall) const override
    {
      return die.plane(wall);
    }

    int
    sums_slot(const int wall) const override
    {
      return wall < 2 ? wall : 2;
    }

  private:
    const SquareDie &die;
  };

  /**
   * The cylindrical die of DieWalls (axis z through the origin, flat
   * punches), numbered by Wall: lower punch, upper punch, die wall. The die
   * wall's outward normal is e_r = (x, y, 0) / r, which turns with the
   * centre: d e_r / dx v = (I - e_r e_r^T) (v_x, v_y, 0) / r.
   */
  class CylinderDieWalls final : public NonlocalWalls
  {
  public:
    explicit CylinderDieWalls(const DieWalls &die)
        : die(die)
    {
    }

    int
    n_walls() const override
    {
      return n_walls_;
    }

    double
    distance(const int wall, const Eigen::Vector3d &x) const override
    {
      switch (wall)
        {
          case 0:
            return x[2] - die.lower_punch;
          case 1:
            return die.upper_punch - x[2];
          default:
            return die.die_present ? die.radius() - std::hypot(x[0], x[1])
                                   : std::numeric_limits<double>::infinity();
        }
    }

    Eigen::Vector3d
    outward_normal(const int wall, const Eigen::Vector3d &x) const override
    {
      switch (wall)
        {
          case 0:
            return -Eigen::Vector3d::UnitZ();
          case 1:
            return Eigen::Vector3d::UnitZ();
          default:
            {
              const double r = std::hypot(x[0], x[1]);
              return r > 0.0 ? Eigen::Vector3d(x[0] / r, x[1] / r, 0.0)
                             : Eigen::Vector3d::UnitX();
            }
        }
    }

    Eigen::Vector3d
    normal_derivative(const int              wall,
                      const Eigen::Vector3d &x,
                      const Eigen::Vector3d &v) const override
    {
      if (wall != 2)
        return Eigen::Vector3d::Zero();
      const double r = std::hypot(x[0], x[1]);
      if (!(r > 0.0))
        return Eigen::Vector3d::Zero();
      const Eigen::Vector3d e(x[0] / r, x[1] / r, 0.0);
      const Eigen::Vector3d h(v[0], v[1], 0.0);
      return (h - e * e.dot(h)) / r;
    }

    double
    position(const int wall) const override
    {
      switch (wall)
        {
          case 0:
            return die.lower_punch;
          case 1:
            return die.upper_punch;
          default:
            return die.die_present ? die.radius() : -1.0;
        }
    }

    int
    sums_slot(const int wall) const override
    {
      return wall;
    }

  private:
    static constexpr int n_walls_ = 3;
    const DieWalls      &die;
  };
} // namespace compax::dem

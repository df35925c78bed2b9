#include "dem/walls/die_walls.h"

#include "dem/numbers.h"

#include <cmath>

namespace compax::dem
{
  double
  DieWalls::punch_area() const
  {
    return 0.25 * pi * diameter * diameter;
  }

  double
  DieWalls::enclosed_volume() const
  {
    return punch_area() * height();
  }

  double
  DieWalls::wall_area() const
  {
    return pi * diameter * height();
  }

  WallGap
  DieWalls::gap(const Wall wall, const Eigen::Vector3d &x, const double R) const
  {
    WallGap g;
    switch (wall)
      {
        case Wall::lower_punch:
          g.overlap = R - (x[2] - lower_punch);
          g.normal  = Eigen::Vector3d::UnitZ();
          break;
        case Wall::upper_punch:
          g.overlap = R - (upper_punch - x[2]);
          g.normal  = -Eigen::Vector3d::UnitZ();
          break;
        case Wall::die:
          {
            const double r  = std::hypot(x[0], x[1]);
            g.axis_distance = r;
            g.overlap       = die_present ? R + r - radius() : -R;
            if (r > 0.0)
              g.normal = Eigen::Vector3d(-x[0] / r, -x[1] / r, 0.0);
            else
              g.normal = -Eigen::Vector3d::UnitX();
            break;
          }
      }
    return g;
  }

  double
  DieWalls::coordinate(const Wall wall) const
  {
    switch (wall)
      {
        case Wall::lower_punch:
          return lower_punch;
        case Wall::upper_punch:
          return upper_punch;
        case Wall::die:
          return die_present ? radius() : 1e300;
      }
    return 0.0;
  }
} // namespace compax::dem

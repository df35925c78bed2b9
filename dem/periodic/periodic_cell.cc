#include "dem/periodic/periodic_cell.h"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  PeriodicCell::PeriodicCell(const Eigen::Matrix3d    &lattice,
                             const std::array<bool, 3> periodic)
      : is_periodic(periodic)
  {
    set_lattice(lattice);
  }

  PeriodicCell
  PeriodicCell::box(const Eigen::Vector3d    &lengths,
                    const std::array<bool, 3> periodic)
  {
    return PeriodicCell(lengths.asDiagonal().toDenseMatrix(), periodic);
  }

  void
  PeriodicCell::set_lattice(const Eigen::Matrix3d &lattice)
  {
    const double det = lattice.determinant();
    if (!(std::abs(det) > 0.0) || !std::isfinite(det))
      throw std::invalid_argument("PeriodicCell: singular lattice");
    H     = lattice;
    H_inv = lattice.inverse();
  }

  Eigen::Vector3d
  PeriodicCell::image_offset(const LatticeImage &n) const
  {
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    for (int d = 0; d < 3; ++d)
      if (is_periodic[d] && n[d] != 0)
        offset += H.col(d) * static_cast<double>(n[d]);
    return offset;
  }

  LatticeImage
  PeriodicCell::wrap(Eigen::Vector3d &x) const
  {
    LatticeImage    n{0, 0, 0};
    Eigen::Vector3d s     = H_inv * x;
    bool            moved = false;
    for (int d = 0; d < 3; ++d)
      if (is_periodic[d])
        {
          const double k = std::floor(s[d]);
          if (k != 0.0)
            {
              n[d] = static_cast<std::int32_t>(k);
              s[d] -= k;
              moved = true;
            }
        }
    if (moved)
      x -= image_offset(n);
    return n;
  }

  Eigen::Vector3d
  PeriodicCell::minimum_image(const Eigen::Vector3d &d) const
  {
    Eigen::Vector3d s = H_inv * d;
    LatticeImage    n{0, 0, 0};
    for (int a = 0; a < 3; ++a)
      if (is_periodic[a])
        n[a] = static_cast<std::int32_t>(std::round(s[a]));
    return d - image_offset(n);
  }

  double
  PeriodicCell::width(const int axis) const
  {
    const int j = (axis + 1) % 3, k = (axis + 2) % 3;
    return volume() / H.col(j).cross(H.col(k)).norm();
  }

  double
  PeriodicCell::volume() const
  {
    return std::abs(H.determinant());
  }
} // namespace compax::dem

#include "dem/nonlocal/square_die.h"

namespace compax::dem
{
  Eigen::Vector3d
  SquareDie::outward_normal(const int face)
  {
    static const std::array<Eigen::Vector3d, n_faces> normals{
      {Eigen::Vector3d(0, 0, -1),
       Eigen::Vector3d(0, 0, 1),
       Eigen::Vector3d(-1, 0, 0),
       Eigen::Vector3d(1, 0, 0),
       Eigen::Vector3d(0, -1, 0),
       Eigen::Vector3d(0, 1, 0)}};
    return normals[face];
  }

  double
  SquareDie::plane(const int face) const
  {
    switch (face)
      {
        case lower_punch:
          return -lower_punch_height;
        case upper_punch:
          return upper_punch_height;
        default:
          return 0.5 * width;
      }
  }

  double
  SquareDie::distance(const int face, const Eigen::Vector3d &x) const
  {
    return plane(face) - outward_normal(face).dot(x);
  }

  const char *
  SquareDie::face_name(const int face)
  {
    static const char *names[n_faces] = {
      "lower_punch", "upper_punch", "x_lower", "x_upper", "y_lower", "y_upper"};
    return names[face];
  }
} // namespace compax::dem

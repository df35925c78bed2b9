#pragma once

#include "dem/contact/contact_response.h"

#include <Eigen/Core>

namespace compax::dem
{
  /**
   * The 3x3 stiffness block of a central contact force P(gamma) between
   * two centres at separation d (gamma = R_i + R_j - |d|), written as
   * k = a n n^T + b I with n = d/|d|:
   * k = P' n n^T - P/|d| (I - n n^T), the normal term from the law's
   * exact dP/dgamma and the geometric term from the turning normal.
   */
  struct PairBlock
  {
    double a;
    double b;

    PairBlock(const ContactResponse &r, const double distance)
        : a(r.stiffness + r.force / distance)
        , b(-r.force / distance)
    {
    }

    /// block += sign * (a n n^T + b I), row-major 3x3.
    void
    add_to(double *block, const double sign, const Eigen::Vector3d &n) const
    {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          block[3 * r + c] += sign * (a * n[r] * n[c] + (r == c ? b : 0.0));
    }

    Eigen::Matrix3d
    matrix(const Eigen::Vector3d &n) const
    {
      return a * n * n.transpose() + b * Eigen::Matrix3d::Identity();
    }
  };
} // namespace compax::dem

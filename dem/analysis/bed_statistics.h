#pragma once

#include "dem/solver/bed.h"

#include <Eigen/Core>

#include <vector>

namespace compax::dem
{
  /// The particle-particle contacts of a bed that carry a force, as the
  /// fabric and force-network analyses of Gonzalez 2018 Sec. 5.5 use them.
  struct ContactNetwork
  {
    /// Unit normals (x_i - x_j)/|x_i - x_j| of the loaded contacts.
    std::vector<Eigen::Vector3d> normals;
    /// Their forces P [N]: positive compressive, negative tensile.
    std::vector<double> forces;
  };

  /// The loaded particle-particle contacts at the bed's current positions.
  ContactNetwork
  loaded_contacts(const Bed &bed);

  /// A histogram of contact forces over equal bins between the smallest and
  /// largest force (Fig. 16: compressive and tensile forces together).
  struct ForceHistogram
  {
    /// Bin centres [N] and counts.
    std::vector<double>      centres;
    std::vector<std::size_t> counts;
  };

  ForceHistogram
  force_histogram(const std::vector<double> &forces, unsigned int bins);
} // namespace compax::dem

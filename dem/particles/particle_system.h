#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace compax::dem
{
  /**
   * The spheres of a granular bed stored as flat arrays (structure of
   * arrays), so that the equilibrium solver can view all coordinates as one
   * vector x = (x_1^T, ..., x_N^T)^T without copying.
   */
  struct ParticleSystem
  {
    /// Centres [m]; Eigen::Vector3d is three packed doubles, so
    /// positions[0].data() addresses the whole 3N vector.
    std::vector<Eigen::Vector3d> positions;
    /// Radii [m].
    std::vector<double> radii;
    /// Index of each particle's material in the bed's material table.
    std::vector<unsigned int> materials;

    std::size_t
    size() const
    {
      return radii.size();
    }

    void
    add(const Eigen::Vector3d &x, double radius, unsigned int material = 0);

    /// Sum of the sphere volumes [m^3].
    double
    solid_volume() const;

    /// Mean radius [m] (0 for an empty system).
    double
    mean_radius() const;

    /// Largest radius [m].
    double
    max_radius() const;

    /// All coordinates as one writable vector of length 3N.
    Eigen::Map<Eigen::VectorXd>
    coordinates();

    Eigen::Map<const Eigen::VectorXd>
    coordinates() const;
  };
} // namespace compax::dem

#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <utility>
#include <vector>

namespace compax::dem
{
  /// A pair of particle indices i < j.
  using ParticlePair = std::pair<std::uint32_t, std::uint32_t>;

  /**
   * Uniform grid of cubic cells (linked cells) over the bounding box of the
   * particles, built with a counting sort into flat arrays. Finds all pairs
   * whose surfaces are closer than a margin in O(N) for a bounded radius
   * ratio.
   */
  class CellGrid
  {
  public:
    /**
     * Pairs (i < j) with |x_i - x_j| < R_i + R_j + margin, sorted by (i, j).
     * The cell size is 2 R_max + margin. Reuses the grid's own buffers.
     */
    void
    find_pairs(const std::vector<Eigen::Vector3d> &positions,
               const std::vector<double>          &radii,
               double                              margin,
               std::vector<ParticlePair>          &pairs);

  private:
    std::vector<std::uint32_t> cell_start;
    std::vector<std::uint32_t> cell_particles;
    std::vector<std::uint32_t> particle_cell;
  };

  /// The same pairs by the O(N^2) double loop (reference for tests).
  std::vector<ParticlePair>
  brute_force_pairs(const std::vector<Eigen::Vector3d> &positions,
                    const std::vector<double>          &radii,
                    double                              margin);
} // namespace compax::dem

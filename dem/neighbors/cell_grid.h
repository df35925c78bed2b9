#pragma once

#include <Eigen/Core>

#include <cstddef>
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
     * From parallel_particles particles on, the threads search contiguous
     * ranges of i, each sorts its own, and the ranges are joined in order:
     * the same sorted list as one thread's.
     */
    void
    find_pairs(const std::vector<Eigen::Vector3d> &positions,
               const std::vector<double>          &radii,
               double                              margin,
               std::vector<ParticlePair>          &pairs);

  private:
    /// The cell of a point, clamped to the grid, as (x, y, z) indices and
    /// as the flat index (z dims[1] + y) dims[0] + x.
    void
    cell_of(const Eigen::Vector3d &x, int c[3]) const;
    std::uint32_t
    cell_index(const Eigen::Vector3d &x) const;

    /// The pairs of particle i with the particles of its own and the 26
    /// neighbouring cells that lie beyond it (j > i), unsorted.
    void
    add_pairs_of(std::uint32_t                       i,
                 const std::vector<Eigen::Vector3d> &positions,
                 const std::vector<double>          &radii,
                 double                              margin,
                 std::vector<ParticlePair>          &pairs) const;

    Eigen::Vector3d lo      = Eigen::Vector3d::Zero();
    double          cell    = 0.0;
    int             dims[3] = {1, 1, 1};
    /// Each thread's pairs of the last parallel search.
    std::vector<std::vector<ParticlePair>> thread_pairs;
    std::vector<std::uint32_t>             cell_start;
    std::vector<std::uint32_t>             cell_particles;
    std::vector<std::uint32_t>             particle_cell;
  };

  /// The same pairs by the O(N^2) double loop (reference for tests).
  std::vector<ParticlePair>
  brute_force_pairs(const std::vector<Eigen::Vector3d> &positions,
                    const std::vector<double>          &radii,
                    double                              margin);
} // namespace compax::dem

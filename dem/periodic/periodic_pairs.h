#pragma once

#include "dem/periodic/periodic_cell.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /**
   * Particles i < j whose surfaces come closer than a margin when j is
   * translated by the lattice image n: the separation is
   * x_j - x_i + H n for the positions as given (unwrapped).
   */
  struct ImagePair
  {
    std::uint32_t i;
    std::uint32_t j;
    LatticeImage  image;

    /// Order by (i, j, image), the order find_pairs() returns.
    bool
    operator<(const ImagePair &other) const
    {
      if (i != other.i)
        return i < other.i;
      if (j != other.j)
        return j < other.j;
      return image < other.image;
    }

    bool
    operator==(const ImagePair &other) const
    {
      return i == other.i && j == other.j && image == other.image;
    }
  };

  /**
   * Linked cells over the fractional coordinates of a PeriodicCell: bins
   * wrap around along periodic directions and cover the particles' extent
   * along the others. O(N) for a bounded radius ratio; the buffers are
   * reused from call to call. A periodic direction needs a width of at
   * least 2 R_max + margin (then the 27-bin stencil, with its images, holds
   * every neighbour, also when the cell is only one or two bins wide; a
   * pair may then touch through more than one image, each its own entry).
   */
  class PeriodicCellGrid
  {
  public:
    /// All image pairs with |x_j - x_i + H n| < R_i + R_j + margin, sorted.
    void
    find_pairs(const PeriodicCell                 &cell,
               const std::vector<Eigen::Vector3d> &positions,
               const std::vector<double>          &radii,
               double                              margin,
               std::vector<ImagePair>             &pairs);

  private:
    std::vector<Eigen::Vector3d> wrapped;
    std::vector<LatticeImage>    shift;
    std::vector<std::uint32_t>   bin_of;
    std::vector<std::uint32_t>   bin_start;
    std::vector<std::uint32_t>   bin_particles;
    std::vector<std::uint32_t>   bin_cursor;
  };

  /// The same pairs by trying every pair and every image n with
  /// |n_d| <= max_image along the periodic directions (reference for
  /// tests).
  std::vector<ImagePair>
  brute_force_image_pairs(const PeriodicCell                 &cell,
                          const std::vector<Eigen::Vector3d> &positions,
                          const std::vector<double>          &radii,
                          double                              margin,
                          int                                 max_image = 2);
} // namespace compax::dem

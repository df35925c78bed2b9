#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace compax::dem
{
  /**
   * Neighbour search of a ballistic deposition: columns of cubic cells over
   * the cross-section [-w/2, w/2)^2, growing upwards, so that a falling
   * sphere meets only the spheres of the 3 x 3 columns around it (O(N) for
   * a bounded radius ratio). In a periodic column the neighbourhood wraps
   * around (and every column is searched when there are fewer than three).
   */
  class DepositionGrid
  {
  public:
    /// Cells at least `reach` wide; in a periodic column a whole number of
    /// them spans the width, so that the wrapped neighbours of a boundary
    /// column are the ones across the periodic face.
    DepositionGrid(const double width, const double reach, const bool periodic)
        : half(0.5 * width)
        , cell(periodic ? width / std::max(1.0, std::floor(width / reach))
                        : reach)
        , n_xy(std::max(1,
                        static_cast<int>(periodic ? std::round(width / cell)
                                                  : std::ceil(width / cell))))
        , periodic(periodic)
        , columns(n_xy * n_xy)
    {
    }

    /// Files sphere @p i, centred at @p x.
    void
    insert(const Eigen::Vector3d &x, const std::uint32_t i)
    {
      auto     &col = columns[column(x)];
      const int zb  = z_bin(x[2]);
      if (static_cast<int>(col.size()) <= zb)
        col.resize(zb + 1);
      col[zb].push_back(i);
    }

    /// Calls f(j) for every sphere in the 3x3 columns around x, in the z
    /// bins next to x's (all heights if all_heights), row by row. A
    /// periodic grid of fewer than three columns a side visits each column
    /// once.
    template <typename Function>
    void
    for_each_near(const Eigen::Vector3d &x,
                  const bool             all_heights,
                  Function               f) const
    {
      const int  cx = xy_bin(x[0]), cy = xy_bin(x[1]), cz = z_bin(x[2]);
      const auto visit = [&](const int ix, const int iy) {
        const auto &col = columns[iy * n_xy + ix];
        const int   lo  = all_heights ? 0 : std::max(0, cz - 1);
        const int   hi  = all_heights ? static_cast<int>(col.size()) - 1
                                      : std::min<int>(cz + 1, col.size() - 1);
        for (int z = lo; z <= hi; ++z)
          for (const std::uint32_t j : col[z])
            f(j);
      };
      if (!periodic)
        {
          for (int iy = std::max(0, cy - 1); iy <= std::min(n_xy - 1, cy + 1);
               ++iy)
            for (int ix = std::max(0, cx - 1); ix <= std::min(n_xy - 1, cx + 1);
                 ++ix)
              visit(ix, iy);
          return;
        }
      if (n_xy < 3)
        {
          for (int k = 0; k < n_xy * n_xy; ++k)
            visit(k % n_xy, k / n_xy);
          return;
        }
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          visit((cx + dx + n_xy) % n_xy, (cy + dy + n_xy) % n_xy);
    }

  private:
    int
    xy_bin(const double v) const
    {
      return std::clamp(static_cast<int>((v + half) / cell), 0, n_xy - 1);
    }

    int
    z_bin(const double z) const
    {
      return std::max(0, static_cast<int>(z / cell));
    }

    std::size_t
    column(const Eigen::Vector3d &x) const
    {
      return xy_bin(x[1]) * n_xy + xy_bin(x[0]);
    }

    double                                               half, cell;
    int                                                  n_xy;
    bool                                                 periodic;
    std::vector<std::vector<std::vector<std::uint32_t>>> columns;
  };
} // namespace compax::dem

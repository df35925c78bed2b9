#include "dem/neighbors/cell_grid.h"

#include "dem/parallel_particles.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <omp.h>

namespace compax::dem
{
  void
  CellGrid::find_pairs(const std::vector<Eigen::Vector3d> &positions,
                       const std::vector<double>          &radii,
                       const double                        margin,
                       std::vector<ParticlePair>          &pairs)
  {
    pairs.clear();
    const std::size_t n = positions.size();
    if (n < 2)
      return;

    lo                    = positions[0];
    Eigen::Vector3d hi    = positions[0];
    double          r_max = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      {
        lo    = lo.cwiseMin(positions[i]);
        hi    = hi.cwiseMax(positions[i]);
        r_max = std::max(r_max, radii[i]);
      }
    cell = 2.0 * r_max + margin;
    // Keep the grid at most ~8 cells per particle even if a few particles
    // are far away: coarser cells stay correct, only slower.
    for (;;)
      {
        double count = 1.0;
        for (int d = 0; d < 3; ++d)
          count *= std::floor((hi[d] - lo[d]) / cell) + 1.0;
        if (count <= 8.0 * n + 64.0)
          break;
        cell *= 2.0;
      }
    for (int d = 0; d < 3; ++d)
      dims[d] = std::max(1, static_cast<int>((hi[d] - lo[d]) / cell) + 1);
    const std::size_t n_cells
      = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];

    particle_cell.resize(n);
    cell_start.assign(n_cells + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
      {
        particle_cell[i] = cell_index(positions[i]);
        ++cell_start[particle_cell[i] + 1];
      }
    for (std::size_t c = 0; c < n_cells; ++c)
      cell_start[c + 1] += cell_start[c];
    cell_particles.resize(n);
    {
      std::vector<std::uint32_t> next(cell_start.begin(), cell_start.end() - 1);
      for (std::size_t i = 0; i < n; ++i)
        cell_particles[next[particle_cell[i]]++]
          = static_cast<std::uint32_t>(i);
    }

    if (static_cast<std::ptrdiff_t>(n) < parallel_particles)
      {
        for (std::size_t i = 0; i < n; ++i)
          add_pairs_of(
            static_cast<std::uint32_t>(i), positions, radii, margin, pairs);
        std::sort(pairs.begin(), pairs.end());
        return;
      }
    // A static schedule without a chunk size gives each thread one range
    // of i, in thread order.
    thread_pairs.resize(static_cast<std::size_t>(omp_get_max_threads()));
    const auto n_signed = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel
    {
      std::vector<ParticlePair> &mine
        = thread_pairs[static_cast<std::size_t>(omp_get_thread_num())];
      mine.clear();
#pragma omp for schedule(static) nowait
      for (std::ptrdiff_t i = 0; i < n_signed; ++i)
        add_pairs_of(
          static_cast<std::uint32_t>(i), positions, radii, margin, mine);
      std::sort(mine.begin(), mine.end());
    }
    std::size_t total = 0;
    for (const auto &t : thread_pairs)
      total += t.size();
    pairs.reserve(total);
    for (const auto &t : thread_pairs)
      pairs.insert(pairs.end(), t.begin(), t.end());
  }

  std::uint32_t
  CellGrid::cell_index(const Eigen::Vector3d &x) const
  {
    int c[3];
    cell_of(x, c);
    return static_cast<std::uint32_t>((c[2] * dims[1] + c[1]) * dims[0] + c[0]);
  }

  void
  CellGrid::cell_of(const Eigen::Vector3d &x, int c[3]) const
  {
    for (int d = 0; d < 3; ++d)
      c[d] = std::min(dims[d] - 1, static_cast<int>((x[d] - lo[d]) / cell));
  }

  void
  CellGrid::add_pairs_of(const std::uint32_t                 i,
                         const std::vector<Eigen::Vector3d> &positions,
                         const std::vector<double>          &radii,
                         const double                        margin,
                         std::vector<ParticlePair>          &pairs) const
  {
    int c[3];
    cell_of(positions[i], c);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          {
            const int x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
            if (x < 0 || y < 0 || z < 0 || x >= dims[0] || y >= dims[1]
                || z >= dims[2])
              continue;
            const std::size_t k = (z * dims[1] + y) * dims[0] + x;
            for (std::uint32_t q = cell_start[k]; q < cell_start[k + 1]; ++q)
              {
                const std::uint32_t j = cell_particles[q];
                if (j <= i)
                  continue;
                const double reach = radii[i] + radii[j] + margin;
                if ((positions[i] - positions[j]).squaredNorm() < reach * reach)
                  pairs.emplace_back(i, j);
              }
          }
  }

  std::vector<ParticlePair>
  brute_force_pairs(const std::vector<Eigen::Vector3d> &positions,
                    const std::vector<double>          &radii,
                    const double                        margin)
  {
    std::vector<ParticlePair> pairs;
    for (std::size_t i = 0; i < positions.size(); ++i)
      for (std::size_t j = i + 1; j < positions.size(); ++j)
        {
          const double reach = radii[i] + radii[j] + margin;
          if ((positions[i] - positions[j]).squaredNorm() < reach * reach)
            pairs.emplace_back(static_cast<std::uint32_t>(i),
                               static_cast<std::uint32_t>(j));
        }
    return pairs;
  }
} // namespace compax::dem

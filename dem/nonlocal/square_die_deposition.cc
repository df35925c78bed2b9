#include "dem/nonlocal/square_die_deposition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// Columns of cubic cells over the square cross-section.
    class ColumnGrid
    {
    public:
      ColumnGrid(const double width, const double cell)
          : half(0.5 * width)
          , cell(cell)
          , n(std::max(1, static_cast<int>(std::ceil(width / cell))))
          , columns(n * n)
      {
      }

      void
      insert(const Eigen::Vector3d &x, const std::uint32_t i)
      {
        auto     &col = columns[bin(x[1]) * n + bin(x[0])];
        const int z   = z_bin(x[2]);
        if (static_cast<int>(col.size()) <= z)
          col.resize(z + 1);
        col[z].push_back(i);
      }

      /// f(j) for the particles in the 3x3 columns around x, at all
      /// heights or in the z bins next to x's.
      template <typename Function>
      void
      for_each_near(const Eigen::Vector3d &x, const bool all, Function f) const
      {
        const int cx = bin(x[0]), cy = bin(x[1]), cz = z_bin(x[2]);
        for (int iy = std::max(0, cy - 1); iy <= std::min(n - 1, cy + 1); ++iy)
          for (int ix = std::max(0, cx - 1); ix <= std::min(n - 1, cx + 1);
               ++ix)
            {
              const auto &col = columns[iy * n + ix];
              const int   lo  = all ? 0 : std::max(0, cz - 1);
              const int   hi  = all ? static_cast<int>(col.size()) - 1
                                    : std::min<int>(cz + 1, col.size() - 1);
              for (int z = lo; z <= hi; ++z)
                for (const std::uint32_t j : col[z])
                  f(j);
            }
      }

    private:
      int
      bin(const double v) const
      {
        return std::clamp(static_cast<int>((v + half) / cell), 0, n - 1);
      }

      int
      z_bin(const double z) const
      {
        return std::max(0, static_cast<int>(z / cell));
      }

      double                                               half, cell;
      int                                                  n;
      std::vector<std::vector<std::vector<std::uint32_t>>> columns;
    };
  } // namespace

  ParticleSystem
  square_die_deposition(const SquareDepositionParameters &prm)
  {
    if (prm.sizes.size() != prm.counts.size() || prm.sizes.empty())
      throw std::invalid_argument("one particle count per size distribution");
    double r_max = 0.0;
    for (const auto &s : prm.sizes)
      r_max = std::max(r_max, s.largest());
    if (2.0 * r_max >= prm.width)
      throw std::invalid_argument("particles do not fit into the die");

    RandomSource random(prm.seed);
    // Materials in a random order (Fisher-Yates with our own generator).
    std::vector<unsigned int> order;
    for (std::size_t m = 0; m < prm.counts.size(); ++m)
      order.insert(order.end(), prm.counts[m], static_cast<unsigned int>(m));
    for (std::size_t k = order.size(); k > 1; --k)
      {
        const auto j = static_cast<std::size_t>(random.uniform() * k);
        std::swap(order[k - 1], order[std::min(j, k - 1)]);
      }

    ParticleSystem p;
    ColumnGrid     grid(prm.width, 2.0 * r_max);
    const double   half = 0.5 * prm.width;
    for (const unsigned int material : order)
      {
        const double R            = prm.sizes[material].sample(random);
        const double reach        = half - R;
        const auto   inside_walls = [&](Eigen::Vector3d &q) {
          bool moved = false;
          for (int a = 0; a < 2; ++a)
            if (std::abs(q[a]) > reach)
              {
                q[a]  = std::copysign(reach, q[a]);
                moved = true;
              }
          if (q[2] < R)
            {
              q[2]  = R;
              moved = true;
            }
          return moved;
        };
        Eigen::Vector3d x(random.uniform(-reach, reach),
                          random.uniform(-reach, reach),
                          R);
        // Fall: the highest first contact below.
        grid.for_each_near(x, true, [&](const std::uint32_t j) {
          const Eigen::Vector3d &y  = p.positions[j];
          const double           s  = R + p.radii[j];
          const double           h2 = (x.head<2>() - y.head<2>()).squaredNorm();
          if (h2 < s * s)
            x[2] = std::max(x[2], y[2] + std::sqrt(s * s - h2));
        });
        // Projection of a trial position out of every overlap.
        const auto project = [&](Eigen::Vector3d &q) {
          for (int sweep = 0; sweep < 200; ++sweep)
            {
              bool moved = inside_walls(q);
              grid.for_each_near(q, false, [&](const std::uint32_t j) {
                const Eigen::Vector3d d    = q - p.positions[j];
                const double          s    = R + p.radii[j];
                const double          dist = d.norm();
                if (dist < s * (1.0 - 1e-13))
                  {
                    q = p.positions[j]
                        + (dist > 0.0 ? (d / dist).eval()
                                      : Eigen::Vector3d::UnitZ().eval())
                            * s;
                    moved = true;
                  }
              });
              if (!moved)
                return true;
            }
          return false;
        };
        // Roll down.
        double h = 0.25 * R;
        for (int it = 0; it < 100000 && h > 1e-6 * R; ++it)
          {
            Eigen::Vector3d q = x;
            q[2] -= h;
            if (project(q) && q[2] < x[2] - 1e-9 * h)
              {
                x = q;
                h = std::min(0.25 * R, 1.2 * h);
              }
            else
              h *= 0.5;
          }
        p.add(x, R, material);
        grid.insert(x, static_cast<std::uint32_t>(p.size() - 1));
      }
    return p;
  }
} // namespace compax::dem

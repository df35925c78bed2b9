#include "dem/packing/ballistic_deposition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// Columns of cubic cells over the die cross-section, growing upwards.
    class DepositionGrid
    {
    public:
      DepositionGrid(double die_radius, double cell)
          : r_die(die_radius)
          , cell(cell)
          , n_xy(
              std::max(1, static_cast<int>(std::ceil(2 * die_radius / cell))))
          , columns(n_xy * n_xy)
      {
      }

      void
      insert(const ParticleSystem &p, std::uint32_t i)
      {
        auto     &col = columns[column(p.positions[i])];
        const int zb  = z_bin(p.positions[i][2]);
        if (static_cast<int>(col.size()) <= zb)
          col.resize(zb + 1);
        col[zb].push_back(i);
      }

      /// Calls f(j) for every particle in the 3x3 columns around x, within
      /// z bins [z_lo, z_hi] (all if z_hi < z_lo).
      template <typename Function>
      void
      for_each_near(const Eigen::Vector3d &x,
                    bool                   all_heights,
                    Function               f) const
      {
        const int cx = xy_bin(x[0]), cy = xy_bin(x[1]), cz = z_bin(x[2]);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            {
              const int ix = cx + dx, iy = cy + dy;
              if (ix < 0 || iy < 0 || ix >= n_xy || iy >= n_xy)
                continue;
              const auto &col = columns[iy * n_xy + ix];
              const int   lo  = all_heights ? 0 : std::max(0, cz - 1);
              const int   hi  = all_heights
                                  ? static_cast<int>(col.size()) - 1
                                  : std::min<int>(cz + 1, col.size() - 1);
              for (int z = lo; z <= hi; ++z)
                for (const std::uint32_t j : col[z])
                  f(j);
            }
      }

    private:
      int
      xy_bin(double v) const
      {
        return std::clamp(static_cast<int>((v + r_die) / cell), 0, n_xy - 1);
      }
      int
      z_bin(double z) const
      {
        return std::max(0, static_cast<int>(z / cell));
      }
      std::size_t
      column(const Eigen::Vector3d &x) const
      {
        return xy_bin(x[1]) * n_xy + xy_bin(x[0]);
      }

      double                                               r_die, cell;
      int                                                  n_xy;
      std::vector<std::vector<std::vector<std::uint32_t>>> columns;
    };
  } // namespace

  ParticleSystem
  ballistic_deposition(const DepositionParameters &prm)
  {
    RandomSource   random(prm.seed);
    ParticleSystem p;
    const double   r_die = 0.5 * prm.die_diameter;
    const double   r_max = prm.sizes.largest();
    if (2.0 * r_max >= r_die)
      throw std::invalid_argument("particles do not fit into the die");
    DepositionGrid      grid(r_die, 2.0 * r_max);
    std::vector<double> cumulative;
    for (const double f : prm.material_fractions)
      cumulative.push_back((cumulative.empty() ? 0.0 : cumulative.back()) + f);

    for (std::size_t n = 0; n < prm.n_particles; ++n)
      {
        const double R        = prm.sizes.sample(random);
        unsigned int material = 0;
        if (!cumulative.empty())
          {
            const double u = random.uniform() * cumulative.back();
            while (material + 1 < cumulative.size()
                   && u >= cumulative[material])
              ++material;
          }
        // Uniform position in the disk of radius r_die - R.
        const double    reach = r_die - R;
        Eigen::Vector3d x;
        do
          {
            x[0] = random.uniform(-reach, reach);
            x[1] = random.uniform(-reach, reach);
          }
        while (x[0] * x[0] + x[1] * x[1] > reach * reach);

        // Fall: the highest first contact below.
        x[2] = R;
        grid.for_each_near(x, true, [&](std::uint32_t j) {
          const Eigen::Vector3d &y = p.positions[j];
          const double           s = R + p.radii[j];
          const double           h2
            = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]);
          if (h2 < s * s)
            x[2] = std::max(x[2], y[2] + std::sqrt(s * s - h2));
        });

        // Project a trial position out of every overlap.
        auto project = [&](Eigen::Vector3d &q) {
          for (int sweep = 0; sweep < 200; ++sweep)
            {
              bool moved = false;
              if (q[2] < R)
                {
                  q[2]  = R;
                  moved = true;
                }
              const double r = std::hypot(q[0], q[1]);
              if (r > reach)
                {
                  q[0] *= reach / r;
                  q[1] *= reach / r;
                  moved = true;
                }
              grid.for_each_near(q, false, [&](std::uint32_t j) {
                const Eigen::Vector3d d    = q - p.positions[j];
                const double          s    = R + p.radii[j];
                const double          dist = d.norm();
                if (dist < s * (1.0 - 1e-13))
                  {
                    q = p.positions[j]
                        + (dist > 0.0 ? d / dist
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

        // Roll down by projected descent.
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
        grid.insert(p, static_cast<std::uint32_t>(p.size() - 1));
      }
    return p;
  }
} // namespace compax::dem

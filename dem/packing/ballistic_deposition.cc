#include "dem/packing/ballistic_deposition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /**
     * Columns of cubic cells over the cross-section [-w/2, w/2)^2, growing
     * upwards. In a periodic column the 3 x 3 neighbourhood wraps around
     * (and every column is searched when there are fewer than three).
     */
    class DepositionGrid
    {
    public:
      /// Cells at least `reach` wide; in a periodic column a whole number
      /// of them spans the width, so that the wrapped neighbours of a
      /// boundary column are the ones across the periodic face.
      DepositionGrid(double width, double reach, bool periodic)
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

      void
      insert(const ParticleSystem &p, std::uint32_t i)
      {
        auto     &col = columns[column(p.positions[i])];
        const int zb  = z_bin(p.positions[i][2]);
        if (static_cast<int>(col.size()) <= zb)
          col.resize(zb + 1);
        col[zb].push_back(i);
      }

      /// Calls f(j) for every particle in the 3x3 columns around x, in the
      /// z bins next to x's (all heights if all_heights).
      template <typename Function>
      void
      for_each_near(const Eigen::Vector3d &x,
                    bool                   all_heights,
                    Function               f) const
      {
        const int  cx = xy_bin(x[0]), cy = xy_bin(x[1]), cz = z_bin(x[2]);
        const bool every_column = periodic && n_xy < 3;
        const int  reach        = every_column ? 0 : 1;
        for (int dy = -reach; dy <= reach; ++dy)
          for (int dx = -reach; dx <= reach; ++dx)
            for (int k = 0; k < (every_column ? n_xy * n_xy : 1); ++k)
              {
                int ix = every_column ? k % n_xy : cx + dx;
                int iy = every_column ? k / n_xy : cy + dy;
                if (periodic)
                  {
                    ix = (ix + n_xy) % n_xy;
                    iy = (iy + n_xy) % n_xy;
                  }
                else if (ix < 0 || iy < 0 || ix >= n_xy || iy >= n_xy)
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
        return std::clamp(static_cast<int>((v + half) / cell), 0, n_xy - 1);
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

      double                                               half, cell;
      int                                                  n_xy;
      bool                                                 periodic;
      std::vector<std::vector<std::vector<std::uint32_t>>> columns;
    };

    /**
     * The container's lateral geometry: the separation of two centres in x
     * and y (shortest periodic image in a periodic column) and the
     * projection of a centre back inside (die wall, or wrap-around).
     */
    struct Lateral
    {
      bool   periodic;
      double width;

      /// y - x reduced to its shortest image, in x and y only.
      Eigen::Vector3d
      separation(const Eigen::Vector3d &x, const Eigen::Vector3d &y) const
      {
        Eigen::Vector3d d = y - x;
        if (periodic)
          for (int k = 0; k < 2; ++k)
            d[k] -= width * std::round(d[k] / width);
        return d;
      }

      /// Moves q inside; whether it had to move (a periodic wrap is no move).
      bool
      confine(Eigen::Vector3d &q, double R) const
      {
        if (periodic)
          {
            for (int k = 0; k < 2; ++k)
              q[k] -= width * std::floor(q[k] / width + 0.5);
            return false;
          }
        const double reach = 0.5 * width - R;
        const double r     = std::hypot(q[0], q[1]);
        if (r <= reach)
          return false;
        q[0] *= reach / r;
        q[1] *= reach / r;
        return true;
      }
    };
  } // namespace

  ParticleSystem
  ballistic_deposition(const DepositionParameters &prm)
  {
    RandomSource   random(prm.seed);
    ParticleSystem p;
    const bool periodic = prm.container == DepositionContainer::periodic_square;
    const double r_die  = 0.5 * prm.die_diameter;
    const double r_max  = prm.sizes.largest();
    if (2.0 * r_max >= r_die)
      throw std::invalid_argument("particles do not fit into the die");
    const Lateral       lateral{periodic, prm.die_diameter};
    DepositionGrid      grid(prm.die_diameter, 2.0 * r_max, periodic);
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
        // Uniform position in the disk of radius r_die - R, or in the
        // periodic square.
        const double    reach = periodic ? r_die : r_die - R;
        Eigen::Vector3d x;
        do
          {
            x[0] = random.uniform(-reach, reach);
            x[1] = random.uniform(-reach, reach);
          }
        while (!periodic && x[0] * x[0] + x[1] * x[1] > reach * reach);

        // Fall: the highest first contact below.
        x[2] = R;
        grid.for_each_near(x, true, [&](std::uint32_t j) {
          const Eigen::Vector3d d  = lateral.separation(x, p.positions[j]);
          const double          s  = R + p.radii[j];
          const double          h2 = d[0] * d[0] + d[1] * d[1];
          if (h2 < s * s)
            x[2] = std::max(x[2], p.positions[j][2] + std::sqrt(s * s - h2));
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
              moved = lateral.confine(q, R) || moved;
              grid.for_each_near(q, false, [&](std::uint32_t j) {
                const Eigen::Vector3d d
                  = -lateral.separation(q, p.positions[j]);
                const double s    = R + p.radii[j];
                const double dist = d.norm();
                if (dist < s * (1.0 - 1e-13))
                  {
                    // Onto the sphere's surface around its nearest image.
                    const Eigen::Vector3d centre
                      = periodic ? Eigen::Vector3d(q - d) : p.positions[j];
                    q = centre
                        + (dist > 0.0 ? d / dist
                                      : Eigen::Vector3d::UnitZ().eval())
                            * s;
                    if (periodic)
                      lateral.confine(q, R);
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

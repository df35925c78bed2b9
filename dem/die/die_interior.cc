#include "dem/die/die_interior.h"

#include "dem/numbers.h"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <vector>

namespace compax::dem
{
  namespace
  {
    /// The force of a contact below the resolution counts as zero, as in
    /// measure(): the solve determines no force there.
    double
    resolved(const double P, const double resolution)
    {
      return std::abs(P) > resolution ? P : 0.0;
    }
  } // namespace

  InteriorMeasures
  measure_interior(const Bed   &bed,
                   const double wall_distance,
                   const double resolution,
                   const double min_extent)
  {
    const ParticleSystem &p     = bed.particles;
    const DieWalls       &walls = bed.walls;
    const double          r_max = walls.radius() - wall_distance;
    const double          z_lo  = walls.lower_punch + wall_distance;
    const double          z_hi  = walls.upper_punch - wall_distance;

    InteriorMeasures out;
    const double     nan = std::numeric_limits<double>::quiet_NaN();
    out.relative_density = out.sigma_zz = out.sigma_rr = nan;
    if (!(r_max > 0.0 && z_hi > z_lo) || z_hi - z_lo < min_extent
        || 2.0 * r_max < min_extent)
      return out;

    std::vector<char> inside(p.size(), 0);
    double            solid = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        const Eigen::Vector3d &x = p.positions[i];
        if (x.z() > z_lo && x.z() < z_hi && x.head<2>().norm() < r_max)
          {
            inside[i] = 1;
            ++out.particles;
            solid += 4.0 / 3.0 * pi * std::pow(p.radii[i], 3);
          }
      }
    if (out.particles == 0)
      return out;

    // sum_c (x_c - x_i) (x) f_c of each interior particle.
    std::vector<Eigen::Matrix3d> moment(p.size(), Eigen::Matrix3d::Zero());
    for (const PairContact &c : bed.contacts.pairs)
      {
        if (!inside[c.i] && !inside[c.j])
          continue;
        const double gamma = pair_overlap(p, c);
        const double P
          = resolved(law_response(c.law, gamma, c.history).force, resolution);
        if (P == 0.0)
          continue;
        const Eigen::Vector3d d = p.positions[c.j] - p.positions[c.i];
        const Eigen::Vector3d n = d / d.norm();
        // Contact point in the middle of the overlap; force on i is -P n.
        const double branch_i = p.radii[c.i] - 0.5 * gamma;
        const double branch_j = p.radii[c.j] - 0.5 * gamma;
        if (inside[c.i])
          moment[c.i] += (branch_i * n) * (-P * n).transpose();
        if (inside[c.j])
          moment[c.j] += (-branch_j * n) * (P * n).transpose();
      }
    for (const WallContact &c : bed.contacts.walls)
      {
        if (!inside[c.i])
          continue;
        const WallGap g = walls.gap(c.wall, p.positions[c.i], p.radii[c.i]);
        const double  P
          = resolved(law_response(c.law, g.overlap, c.history).force,
                     resolution);
        if (P == 0.0)
          continue;
        // The wall pushes the sphere along g.normal at x - (R - gamma/2) n.
        const double branch = p.radii[c.i] - 0.5 * g.overlap;
        moment[c.i] += (-branch * g.normal) * (P * g.normal).transpose();
      }

    const double volume = pi * r_max * r_max * (z_hi - z_lo);
    double       zz = 0.0, rr = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        if (!inside[i])
          continue;
        const Eigen::Matrix3d m = 0.5 * (moment[i] + moment[i].transpose());
        const Eigen::Vector2d r = p.positions[i].head<2>();
        const double          s = r.norm();
        zz += m(2, 2);
        if (s > 1e-12 * walls.radius())
          {
            const Eigen::Vector2d e = r / s;
            rr += e.dot(m.topLeftCorner<2, 2>() * e);
          }
        else
          rr += 0.5 * (m(0, 0) + m(1, 1));
      }
    out.relative_density = solid / volume;
    out.sigma_zz         = zz / volume;
    out.sigma_rr         = rr / volume;
    return out;
  }
} // namespace compax::dem

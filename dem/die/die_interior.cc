#include "dem/die/die_interior.h"

#include "dem/numbers.h"

#include <Eigen/Core>
#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace compax::dem
{
  namespace
  {
    /// Area [m^2] of the disc of radius a centred at distance s from the
    /// centre of the disc of radius b >= a that lies inside the latter.
    double
    disc_overlap(const double a, const double s, const double b)
    {
      if (a <= 0.0 || s >= a + b)
        return 0.0;
      if (s <= b - a)
        return pi * a * a;
      if (s <= a - b)
        return pi * b * b;
      const double alpha = std::acos(
        std::clamp((s * s + a * a - b * b) / (2.0 * s * a), -1.0, 1.0));
      const double beta = std::acos(
        std::clamp((s * s + b * b - a * a) / (2.0 * s * b), -1.0, 1.0));
      const double k = (-s + a + b) * (s + a - b) * (s - a + b) * (s + a + b);
      return a * a * alpha + b * b * beta - 0.5 * std::sqrt(std::max(k, 0.0));
    }

    /// The force of a contact below the resolution counts as zero, as in
    /// measure(): the solve determines no force there.
    double
    resolved(const double P, const double resolution)
    {
      return std::abs(P) > resolution ? P : 0.0;
    }
  } // namespace

  double
  volume_in_die_region(const Eigen::Vector3d &x,
                       const double           R,
                       const double           r_max,
                       const double           z_lower,
                       const double           z_upper)
  {
    // Slices at heights t in [t1, t2] relative to the centre.
    const double t1 = std::max(-R, z_lower - x.z());
    const double t2 = std::min(R, z_upper - x.z());
    const double s  = x.head<2>().norm();
    if (!(t2 > t1) || s >= r_max + R)
      return 0.0;
    const auto slices
      = [R](const double t) { return R * R * t - t * t * t / 3.0; };
    if (s + R <= r_max)
      return std::max(pi * (slices(t2) - slices(t1)), 0.0);

    // The lens changes form where a slice's radius is |s - r_max|: split
    // there so that each piece is smooth inside (Gauss-Legendre, 25 points
    // per piece, Boost.Math).
    std::array<double, 4> cut{t1, t2, t2, t2};
    const double          d = std::abs(s - r_max);
    std::size_t           n = 1;
    if (d < R)
      for (const double t :
           {-std::sqrt(R * R - d * d), std::sqrt(R * R - d * d)})
        if (t > t1 && t < t2)
          cut[n++] = t;
    cut[n]                = t2;
    const auto slice_area = [&](const double t) {
      return disc_overlap(std::sqrt(std::max(R * R - t * t, 0.0)), s, r_max);
    };
    double volume = 0.0;
    for (std::size_t piece = 0; piece < n; ++piece)
      volume += boost::math::quadrature::gauss<double, 25>::integrate(
        slice_area, cut[piece], cut[piece + 1]);
    return volume;
  }

  InteriorMeasures
  measure_interior(const Bed              &bed,
                   const double            wall_distance,
                   const double            resolution,
                   const double            min_extent,
                   const InteriorWeighting weighting)
  {
    const ParticleSystem &p     = bed.particles;
    const DieWalls       &walls = bed.walls;
    const double          r_max = walls.radius() - wall_distance;
    const double          z_lo  = walls.lower_punch + wall_distance;
    const double          z_hi  = walls.upper_punch - wall_distance;

    InteriorMeasures out;
    const double     nan = std::numeric_limits<double>::quiet_NaN();
    out.relative_density = out.sigma_zz = out.sigma_rr = nan;
    out.coordination_number                            = nan;
    if (!(r_max > 0.0 && z_hi > z_lo) || z_hi - z_lo < min_extent
        || 2.0 * r_max < min_extent)
      return out;

    // weight[i]: the part of sphere i the region counts (InteriorWeighting).
    std::vector<double> weight(p.size(), 0.0);
    double              solid = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        const Eigen::Vector3d &x = p.positions[i];
        const double sphere      = 4.0 / 3.0 * pi * std::pow(p.radii[i], 3);
        if (weighting == InteriorWeighting::volume_fraction)
          weight[i]
            = volume_in_die_region(x, p.radii[i], r_max, z_lo, z_hi) / sphere;
        else
          weight[i]
            = x.z() > z_lo && x.z() < z_hi && x.head<2>().norm() < r_max;
        if (weight[i] > 0.0)
          {
            ++out.particles;
            solid += weight[i] * sphere;
          }
      }
    if (out.particles == 0)
      return out;

    // sum_c (x_c - x_i) (x) f_c and the loaded contacts of each particle.
    std::vector<Eigen::Matrix3d> moment(p.size(), Eigen::Matrix3d::Zero());
    std::vector<int>             loaded(p.size(), 0);
    for (const PairContact &c : bed.contacts.pairs)
      {
        if (weight[c.i] == 0.0 && weight[c.j] == 0.0)
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
        moment[c.i] += (branch_i * n) * (-P * n).transpose();
        moment[c.j] += (-branch_j * n) * (P * n).transpose();
        ++loaded[c.i];
        ++loaded[c.j];
      }
    for (const WallContact &c : bed.contacts.walls)
      {
        if (weight[c.i] == 0.0)
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
        ++loaded[c.i];
      }

    const double volume = pi * r_max * r_max * (z_hi - z_lo);
    double       zz = 0.0, rr = 0.0, contacts = 0.0, weights = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        if (weight[i] == 0.0)
          continue;
        contacts += weight[i] * loaded[i];
        weights += weight[i];
        const Eigen::Matrix3d m
          = 0.5 * weight[i] * (moment[i] + moment[i].transpose());
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
    out.relative_density    = solid / volume;
    out.sigma_zz            = zz / volume;
    out.sigma_rr            = rr / volume;
    out.coordination_number = contacts / weights;
    return out;
  }
} // namespace compax::dem

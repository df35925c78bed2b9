#include "dem/solver/die_bed_system.h"

namespace compax::dem
{
  bool
  DieBedSystem::limit_closing(const Eigen::VectorXd &s,
                              Eigen::VectorXd       &factor) const
  {
    const ParticleSystem &p = bed.particles;
    MeanOverlap           mean;
    for (const PairContact &c : bed.contacts.pairs)
      mean.add(pair_overlap(p, c));
    const double allowance = mean.value(1e-3 * p.mean_radius());
    bool         clipped   = false;
    for (const PairContact &c : bed.contacts.pairs)
      {
        // Only contacts the quadratic model does not see: virgin and apart.
        if (c.history.a_p > 0.0)
          continue;
        const Eigen::Vector3d d     = p.positions[c.i] - p.positions[c.j];
        const double          dist  = d.norm();
        const double          gamma = p.radii[c.i] + p.radii[c.j] - dist;
        if (gamma > 0.0)
          continue;
        const double closing
          = -(s.segment<3>(3 * c.i) - s.segment<3>(3 * c.j)).dot(d) / dist;
        // Both particles share the closing distance.
        clipped |= limit_step_to_gap(factor, c.i, -gamma, closing, allowance);
        clipped |= limit_step_to_gap(factor, c.j, -gamma, closing, allowance);
      }
    for (const WallContact &c : bed.contacts.walls)
      {
        if (c.history.a_p > 0.0)
          continue;
        const WallGap g = bed.walls.gap(c.wall, p.positions[c.i], p.radii[c.i]);
        if (g.overlap > 0.0)
          continue;
        clipped |= limit_step_to_gap(factor,
                                     c.i,
                                     -g.overlap,
                                     -s.segment<3>(3 * c.i).dot(g.normal),
                                     allowance);
      }
    return clipped;
  }
} // namespace compax::dem

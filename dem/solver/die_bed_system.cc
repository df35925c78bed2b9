#include "dem/solver/die_bed_system.h"

namespace compax::dem
{
  bool
  limit_wall_closing(const Bed             &bed,
                     const Eigen::VectorXd &s,
                     const double           allowance,
                     Eigen::VectorXd       &factor)
  {
    const ParticleSystem &p       = bed.particles;
    bool                  clipped = false;
    for (const WallContact &c : bed.contacts.walls)
      {
        if (plastic_radius(c.law, c.history) > 0.0)
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

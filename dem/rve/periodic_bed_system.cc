#include "dem/rve/periodic_bed_system.h"

#include "dem/solver/die_bed_system.h"

namespace compax::dem
{
  bool
  PeriodicBedSystem::limit_closing(const Eigen::VectorXd &s,
                                   Eigen::VectorXd       &factor) const
  {
    const ParticleSystem &p = bed.particles;
    MeanOverlap           mean;
    for (const PeriodicContact &c : bed.contacts.pairs)
      mean.add(p.radii[c.i] + p.radii[c.j]
               - branch_vector(p, bed.cell, c).norm());
    const double allowance = mean.value(1e-3 * p.mean_radius());
    bool         clipped   = false;
    for (const PeriodicContact &c : bed.contacts.pairs)
      {
        if (c.history.a_p > 0.0)
          continue;
        const Eigen::Vector3d d     = branch_vector(p, bed.cell, c);
        const double          dist  = d.norm();
        const double          gamma = p.radii[c.i] + p.radii[c.j] - dist;
        if (gamma > 0.0)
          continue;
        const double closing
          = -(s.segment<3>(3 * c.i) - s.segment<3>(3 * c.j)).dot(d) / dist;
        clipped |= limit_step_to_gap(factor, c.i, -gamma, closing, allowance);
        clipped |= limit_step_to_gap(factor, c.j, -gamma, closing, allowance);
      }
    return clipped;
  }
} // namespace compax::dem

#include "apps/rve/rve_snapshot.h"

#include "dem/io/particle_vtu.h"
#include "dem/rve/periodic_assembler.h"


namespace compax::cli
{
  void
  write_rve_vtu(const std::filesystem::path &file, const dem::PeriodicBed &bed)
  {
    const auto           &p = bed.particles;
    dem::ParticleSnapshot snapshot(p);
    for (const dem::PeriodicContact &c : bed.contacts.pairs)
      {
        const Eigen::Vector3d d     = dem::branch_vector(p, bed.cell, c);
        const double          gamma = p.radii[c.i] + p.radii[c.j] - d.norm();
        const double          P
          = dem::plastic_radius(c.law, c.history) == 0.0 && gamma <= 0.0
              ? 0.0
              : dem::periodic_contact_response(c,
                                               gamma,
                                               dem::ContactBranch::current)
                  .force;
        snapshot.add_contact(c.i, c.j, d.normalized(), P, c.law, c.history);
      }
    for (Eigen::Vector3d &x : snapshot.positions())
      bed.cell.wrap(x);
    snapshot.write(file);
  }

  std::string
  snapshot_name(const int step)
  {
    return "snapshots/rve-" + std::to_string(step) + ".vtu";
  }
} // namespace compax::cli

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
        const dem::PeriodicContactGeometry g
          = dem::contact_geometry(p, bed.cell, c);
        const double P
          = g.may_act
              ? dem::periodic_contact_response(c,
                                               g.overlap,
                                               dem::ContactBranch::current)
                  .force
              : 0.0;
        snapshot.add_contact(
          c.i, c.j, g.branch / g.distance, P, c.law, c.history);
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

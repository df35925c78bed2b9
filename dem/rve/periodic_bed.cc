#include "dem/rve/periodic_bed.h"

namespace compax::dem
{
  void
  map_affinely(PeriodicBed &bed, const Eigen::Matrix3d &F)
  {
    const Eigen::Matrix3d A = F * bed.deformation.inverse();
    for (Eigen::Vector3d &x : bed.particles.positions)
      x = A * x;
    bed.cell.set_lattice(F * bed.reference_lattice);
    bed.deformation = F;
  }
} // namespace compax::dem

#pragma once

#include "dem/particles/particle_system.h"
#include "dem/periodic/periodic_cell.h"
#include "dem/rve/periodic_contact_set.h"

#include <Eigen/Core>

namespace compax::dem
{
  /**
   * A representative volume element: spheres in a fully periodic cell
   * whose lattice H = F H_0 follows the macroscopic deformation gradient F.
   * Positions are unwrapped (they move with F and the fluctuations); a
   * copy of a PeriodicBed is a complete state (trial iterations of a
   * multiscale solver save and restore it).
   */
  struct PeriodicBed
  {
    PeriodicBed()
        : cell(PeriodicCell::box(Eigen::Vector3d::Ones(), {true, true, true}))
    {
    }

    ParticleSystem     particles;
    PeriodicCell       cell;
    PeriodicContactSet contacts;
    /// Lattice of the undeformed cell H_0 [m].
    Eigen::Matrix3d reference_lattice = Eigen::Matrix3d::Identity();
    /// Macroscopic deformation gradient F, H = F H_0 [-].
    Eigen::Matrix3d deformation = Eigen::Matrix3d::Identity();

    /// Solid volume over cell volume [-].
    double
    relative_density() const
    {
      return particles.solid_volume() / cell.volume();
    }
  };

  /// Branch vector of a contact of the cell to the image of j [m].
  inline Eigen::Vector3d
  branch_vector(const PeriodicBed &bed, const PeriodicContact &c)
  {
    return branch_vector(bed.particles, bed.cell, c);
  }

  /// Moves the particles and the lattice of a cell from its deformation
  /// to F by the affine map F F_old^{-1}, without equilibrium (the
  /// predictor of a strain step).
  void
  map_affinely(PeriodicBed &bed, const Eigen::Matrix3d &F);
} // namespace compax::dem

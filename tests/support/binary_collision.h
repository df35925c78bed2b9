#pragma once

// What the explicit-DEM collision tests share: the material, a cell in
// which two spheres collide without wrapping, and a sphere's mass.

#include "dem/dynamics/dem_material.h"
#include "dem/periodic/periodic_cell.h"

#include <Eigen/Core>

#include <cmath>

namespace compax::testing
{
  /// Particles of Young's modulus @p E [Pa], Poisson's ratio @p nu and
  /// density 1541.1 kg/m^3 (Giannis 2021's MCC), with one restitution and
  /// sliding friction for particle-particle and particle-wall contacts.
  inline dem::DemMaterial
  collision_material(const double E,
                     const double nu,
                     const double restitution,
                     const double friction = 0.0)
  {
    dem::DemMaterial m;
    m.youngs_modulus    = E;
    m.poisson_ratio     = nu;
    m.density           = 1541.1;
    m.particle_particle = {restitution, friction, 0.0};
    m.particle_wall     = {restitution, friction, 0.0};
    return m;
  }

  /// A large cell (1 cm), periodic in x and y, so that nothing wraps.
  inline dem::PeriodicCell
  big_cell()
  {
    return dem::PeriodicCell::box(Eigen::Vector3d(1e-2, 1e-2, 1e-2),
                                  {true, true, false});
  }

  /// Mass of a sphere of radius @p R [m] and density @p rho [kg/m^3].
  inline double
  sphere_mass(const double R, const double rho)
  {
    return rho * 4.0 / 3.0 * std::acos(-1.0) * R * R * R;
  }
} // namespace compax::testing

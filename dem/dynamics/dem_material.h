#pragma once

#include "dem/contact/multicontact_adhesive.h"
#include "dem/numbers.h"

#include <Eigen/Core>

#include <cmath>

namespace compax::dem
{
  /// Damping, friction and rolling resistance of one kind of contact
  /// (particle-particle or particle-wall), Giannis 2021 Table 2.
  struct InteractionParameters
  {
    /// Coefficient of restitution e in (0, 1] [-]; sets the dashpot.
    double restitution = 1.0;
    /// Coulomb sliding friction mu (static = dynamic) [-].
    double sliding_friction = 0.0;
    /// Rolling friction mu_r of the constant directional torque (Eq. 5) [-].
    double rolling_friction = 0.0;
  };

  /**
   * Everything the explicit DEM needs to know about the material: the
   * particles' and walls' elastic constants and density, the interaction
   * parameters, and the normal law (Eqs. 6-14; k2/k1 = 1, kc = 0, beta = 0
   * is the conventional Hertz-Mindlin normal force).
   */
  struct DemMaterial
  {
    double youngs_modulus      = 2.58e8;  ///< E of the particles [Pa]
    double poisson_ratio       = 0.30;    ///< nu of the particles [-]
    double density             = 1541.1;  ///< rho of the particles [kg/m^3]
    double wall_youngs_modulus = 7.62e10; ///< E of the plates [Pa]
    double wall_poisson_ratio  = 0.31;    ///< nu of the plates [-]
    InteractionParameters particle_particle;
    InteractionParameters particle_wall;
    /// Normal law; its poisson_ratio is set to the particles' nu.
    MulticontactAdhesiveLaw::Parameters normal_law;
    /// Gravitational acceleration g [m/s^2].
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  };

  /// Shear modulus G = E / (2 (1 + nu)) [Pa].
  inline double
  shear_modulus(const double E, const double nu)
  {
    return E / (2.0 * (1.0 + nu));
  }

  /**
   * Effective shear modulus of Mindlin's tangential stiffness
   * k_t = 8 G* sqrt(R* delta): G* = ((2 - nu1)/G1 + (2 - nu2)/G2)^{-1}
   * [Pa]. Giannis 2021 (after Eq. 3) prints it without the inverse, the
   * same erratum as for E*; a rigid body (G = inf) contributes nothing.
   */
  inline double
  effective_shear_modulus(const double G1,
                          const double nu1,
                          const double G2,
                          const double nu2)
  {
    return 1.0 / ((2.0 - nu1) / G1 + (2.0 - nu2) / G2);
  }

  /**
   * Rayleigh time step of the smallest particle,
   * dt_R = pi R sqrt(rho / G) / (0.1631 nu + 0.8766) [s]: the time a
   * Rayleigh wave takes to cross it, the usual upper bound for an explicit
   * Hertz-Mindlin DEM step (a fraction 0.1-0.3 of it is used).
   */
  inline double
  rayleigh_time_step(const double radius,
                     const double density,
                     const double youngs_modulus,
                     const double poisson_ratio)
  {
    const double G = shear_modulus(youngs_modulus, poisson_ratio);
    return pi * radius * std::sqrt(density / G)
           / (0.1631 * poisson_ratio + 0.8766);
  }
} // namespace compax::dem

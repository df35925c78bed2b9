#pragma once

#include "dem/contact/elastoplastic_material.h"

#include <deal.II/base/parameter_handler.h>

namespace compax::coupling
{
  /// Default values of a particle species, SI units.
  struct ParticleDefaults
  {
    double radius            = 220e-6;
    double youngs_modulus    = 5e9;
    double poisson_ratio     = 0.25;
    double plastic_stiffness = 150e6;
    double plastic_exponent  = 2.0;
    double surface_energy    = 150.0;
  };

  /// Material 1 of Gonzalez 2018, Table 1 (R = 220 um).
  inline constexpr ParticleDefaults material_1{};

  /**
   * Declares, in the current subsection, the entries of one elasto-plastic
   * particle species: Radius, Young's modulus, Poisson's ratio, Plastic
   * stiffness, Plastic exponent, Surface energy.
   */
  void
  declare_particle_material(dealii::ParameterHandler &prm,
                            const ParticleDefaults   &defaults = material_1);

  /// Which bodies a study's solid bridges join.
  enum class BondedBodies
  {
    /// One species in a periodic cell (no walls).
    one_species,
    /// Two species in a die: adds Fracture toughness 2, Cross fracture
    /// toughness and Bridges with walls.
    species_and_walls
  };

  /**
   * Declares the subsection Bonding (Gonzalez 2018 Eqs. 4-5): Fracture
   * toughness from energies, Fracture toughness, Plastic dissipation,
   * Regularization parameter, and for @p bodies = species_and_walls the
   * second species' and the cross toughness and the bridges with walls.
   */
  void
  declare_bonding_parameters(dealii::ParameterHandler &prm,
                             BondedBodies              bodies);

  /// Reads the entries declared by declare_particle_material().
  dem::ElastoplasticMaterial
  get_particle_material(dealii::ParameterHandler &prm);

  /// Reads the "Radius" entry [m] of the current subsection.
  double
  get_particle_radius(dealii::ParameterHandler &prm);

  /// Reads the "Surface energy" entry omega [J/m^2] of the current
  /// subsection.
  double
  get_surface_energy(dealii::ParameterHandler &prm);
} // namespace compax::coupling

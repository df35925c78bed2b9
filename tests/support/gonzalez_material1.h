#pragma once

// Material 1 of Gonzalez 2018, Table 1, the particles of most DEM, RVE and
// FE2 tests: written once, so that the tests cannot drift apart.

#include "dem/contact/elastoplastic_material.h"
#include "dem/solver/contact_model.h"

namespace compax::testing::material1
{
  /// Particle radius R [m].
  inline constexpr double R = 220e-6;
  /// Young's modulus E [Pa].
  inline constexpr double E = 5e9;
  /// Poisson's ratio nu [-].
  inline constexpr double nu = 0.25;
  /// Plastic stiffness kappa [Pa].
  inline constexpr double kappa = 150e6;
  /// Plastic law exponent m [-].
  inline constexpr double m = 2.0;
  /// Fracture toughness of the bridges K_Ic [Pa m^1/2].
  inline constexpr double K_Ic = 1.26e6;

  /// E, nu, kappa and m as the DEM's material.
  inline dem::ElastoplasticMaterial
  elastoplastic()
  {
    return dem::ElastoplasticMaterial{E, nu, kappa, m};
  }

  /// The bonded elasto-plastic contact model of the one material with
  /// K_Ic (default regularization, no bridges with the walls).
  inline dem::ContactModel
  contact_model()
  {
    return dem::ContactModel(elastoplastic(), K_Ic);
  }
} // namespace compax::testing::material1

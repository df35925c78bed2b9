#include "coupling/parameters/material_parameters.h"

#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"

#include <sstream>
#include <string>

namespace compax::coupling
{
  void
  declare_bonding_parameters(dealii::ParameterHandler &prm,
                             const BondedBodies        bodies)
  {
    const bool die = bodies == BondedBodies::species_and_walls;
    prm.enter_subsection("Bonding");
    prm.declare_entry("Fracture toughness from energies",
                      "false",
                      dealii::Patterns::Bool(),
                      "true: K_Ic = sqrt(2 (2 omega + G_p) E) from the "
                      "Material's surface energy omega (Gonzalez 2018 after "
                      "Eq. 5); false: the Fracture toughness entry.");
    input::declare_quantity(
      prm,
      "Fracture toughness",
      "1.26e6",
      input::non_negative(),
      "Pa m^1/2",
      std::string("Fracture toughness K_Ic of the solid bridges between "
                  "particles (Material 1 of Gonzalez 2018, Table 1); 0 "
                  "for no bonding.")
        + (die ? " With two materials: between two particles of Material."
               : ""));
    if (die)
      {
        input::declare_quantity(
          prm,
          "Fracture toughness 2",
          "6.19e6",
          input::non_negative(),
          "Pa m^1/2",
          "K_Ic of bridges between two particles of Material 2 "
          "(used with two materials; Material 2 of Gonzalez 2018, "
          "Table 1).");
        input::declare_quantity(
          prm,
          "Cross fracture toughness",
          "2.62e6",
          input::non_negative(),
          "Pa m^1/2",
          "K_Ic of bridges between a particle of Material and one "
          "of Material 2 (used with two materials). The default is "
          "the formula after Gonzalez 2018 Eq. 5 with the surface "
          "energies of Materials 1 and 2 of Table 1.");
      }
    input::declare_quantity(prm,
                            "Plastic dissipation",
                            "0",
                            input::non_negative(),
                            "J/m^2",
                            "G_p added to the surface energies when K_Ic is "
                            "computed from energies.");
    input::declare_quantity(prm,
                            "Regularization parameter",
                            "0.01",
                            input::positive(),
                            "-",
                            "xi_B of the regularized law, Eq. (4).");
    if (die)
      prm.declare_entry("Bridges with walls",
                        "false",
                        dealii::Patterns::Bool(),
                        "Whether solid bridges form between particles and "
                        "the punches or die wall (same K_Ic).");
    prm.leave_subsection();
  }

  void
  declare_particle_material(dealii::ParameterHandler &prm,
                            const ParticleDefaults   &defaults)
  {
    input::declare_quantity(prm,
                            "Radius",
                            input::format_number(defaults.radius),
                            input::positive(),
                            "m",
                            "Particle radius R.");
    input::declare_quantity(prm,
                            "Young's modulus",
                            input::format_number(defaults.youngs_modulus),
                            input::positive(),
                            "Pa",
                            "Young's modulus E of the particle material.");
    input::declare_quantity(prm,
                            "Poisson's ratio",
                            input::format_number(defaults.poisson_ratio),
                            input::open(-1.0, 0.5),
                            "-",
                            "Poisson's ratio nu, in (-1, 0.5).");
    input::declare_quantity(
      prm,
      "Plastic stiffness",
      input::format_number(defaults.plastic_stiffness),
      input::positive(),
      "Pa",
      "Plastic stiffness kappa of the power-law hardening "
      "sigma = kappa epsilon^(1/m) (Gonzalez 2018, Sec. 2).");
    input::declare_quantity(
      prm,
      "Plastic exponent",
      input::format_number(defaults.plastic_exponent),
      input::RealInterval(1.0, false, 1e3, false),
      "-",
      "Plastic law exponent m >= 1 (m = 1: linear hardening; "
      "large m: perfectly plastic).");
    input::declare_quantity(
      prm,
      "Surface energy",
      input::format_number(defaults.surface_energy),
      input::non_negative(),
      "J/m^2",
      "Interfacial fracture energy omega of the material, "
      "used when the fracture toughness is computed from "
      "energies (Gonzalez 2018, formula after Eq. 5).");
  }

  dem::ElastoplasticMaterial
  get_particle_material(dealii::ParameterHandler &prm)
  {
    dem::ElastoplasticMaterial material;
    material.youngs_modulus    = prm.get_double("Young's modulus");
    material.poisson_ratio     = prm.get_double("Poisson's ratio");
    material.plastic_stiffness = prm.get_double("Plastic stiffness");
    material.plastic_exponent  = prm.get_double("Plastic exponent");
    return material;
  }

  double
  get_particle_radius(dealii::ParameterHandler &prm)
  {
    return prm.get_double("Radius");
  }

  double
  get_surface_energy(dealii::ParameterHandler &prm)
  {
    return prm.get_double("Surface energy");
  }
} // namespace compax::coupling

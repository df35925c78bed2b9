#include "apps/contact/contact_pair.h"

#include "apps/cli/parameters.h"
#include "coupling/parameters/registered_law_parameters.h"
#include "dem/contact/bonded_elastoplastic.h"
#include "dem/contact/contact_law_registry.h"
#include "dem/contact/pair_properties.h"

#include <sstream>

namespace compax::cli
{
  namespace
  {
    /// One body of the pair as read from its subsection.
    struct Body
    {
      dem::ElastoplasticMaterial material;
      double                     radius;
      double                     surface_energy;
    };

    Body
    read_body(dealii::ParameterHandler &prm, const std::string &subsection)
    {
      prm.enter_subsection(subsection);
      Body body{coupling::get_particle_material(prm),
                coupling::get_particle_radius(prm),
                coupling::get_surface_energy(prm)};
      prm.leave_subsection();
      return body;
    }

    std::string
    format(const std::string &label, const double value, const char *unit)
    {
      std::ostringstream out;
      out << label << value << ' ' << unit;
      return out.str();
    }

    ContactPair
    make_bonded_pair(dealii::ParameterHandler &prm,
                     const Body               &body1,
                     const Body               &body2,
                     const bool                wall)
    {
      if (!wall
          && body1.material.plastic_exponent != body2.material.plastic_exponent)
        reject_entry("Particle 2/Plastic exponent",
                     std::to_string(body2.material.plastic_exponent),
                     "the bonded elasto-plastic law needs the same plastic "
                     "exponent m for both particles (Particle 1 has "
                       + std::to_string(body1.material.plastic_exponent) + ")");
      prm.enter_subsection("Bonding");
      const bool from_energies
        = prm.get_bool("Fracture toughness from energies");
      double toughness = prm.get_double("Fracture toughness");
      if (from_energies)
        toughness = dem::fracture_toughness_from_energies(
          body1.material,
          body1.surface_energy,
          body2.material,
          wall ? 0.0 : body2.surface_energy,
          prm.get_double("Plastic dissipation"));
      const bool   regularized = prm.get_bool("Regularized");
      const double xi_B        = prm.get_double("Regularization parameter");
      prm.leave_subsection();

      auto law = std::make_unique<dem::BondedElastoplasticLaw>(
        dem::BondedElastoplasticLaw::for_pair(body1.material,
                                              body1.radius,
                                              body2.material,
                                              body2.radius,
                                              toughness,
                                              xi_B,
                                              regularized));
      ContactPair pair;
      const auto *bonded = law.get();
      pair.closed_forms  = [bonded, toughness](const double gamma_max) {
        const double a_p = bonded->plastic_radius(gamma_max);
        return std::vector<std::string>{
          format("fracture toughness K_Ic  ", toughness, "Pa m^1/2"),
          format("plastic radius a_p       ",
                 a_p,
                 "m (at the largest overlap)"),
          format("closed-form breakage     ",
                 bonded->breakage_overlap(a_p),
                 "m (gamma_p - 3 n_p a_p^(1+1/m) / 4E, Gonzalez 2018 Sec. 3)"),
          format("bonding/elastic energy chi ",
                 bonded->bonding_energy_ratio(a_p),
                 "(Gonzalez 2018 Sec. 3.1)")};
      };
      pair.law = std::move(law);
      return pair;
    }

    /// A law of the registry (contact_law_registry.h), from the values of
    /// its own subsection.
    ContactPair
    make_registered_pair(dealii::ParameterHandler        &prm,
                         const dem::RegisteredContactLaw &law,
                         const Body                      &body1,
                         const Body                      &body2)
    {
      const dem::LawParameterValues values
        = coupling::get_registered_law_values(prm, law);
      const dem::ContactBodies bodies{body1.radius,
                                      body1.material.youngs_modulus,
                                      body1.material.poisson_ratio,
                                      body2.radius,
                                      body2.material.youngs_modulus,
                                      body2.material.poisson_ratio};
      ContactPair              pair;
      pair.law = law.make(values, bodies);
      if (law.context)
        pair.context = law.context(values, bodies);
      return pair;
    }
  } // namespace

  void
  declare_contact_pair(dealii::ParameterHandler         &prm,
                       const coupling::ParticleDefaults &defaults)
  {
    prm.declare_entry("Law",
                      "bonded-elastoplastic",
                      dealii::Patterns::Selection(
                        "bonded-elastoplastic"
                        + coupling::registered_law_names(false)),
                      "Contact law: bonded-elastoplastic (Gonzalez 2018, "
                      "Eqs. 3-5, 13; subsection Bonding)"
                        + coupling::registered_law_documentation(false) + ".");
    prm.declare_entry("Geometry",
                      "sphere-wall",
                      dealii::Patterns::Selection("sphere-sphere|sphere-wall"),
                      "sphere-sphere: Particle 1 against Particle 2; "
                      "sphere-wall: Particle 1 against a rigid flat "
                      "(Particle 2 is then ignored).");
    for (const char *name : {"Particle 1", "Particle 2"})
      {
        prm.enter_subsection(name);
        coupling::declare_particle_material(prm, defaults);
        prm.leave_subsection();
      }
    prm.enter_subsection("Bonding");
    prm.declare_entry("Fracture toughness from energies",
                      "false",
                      dealii::Patterns::Bool(),
                      "true: K_Ic = sqrt(2 (omega1 + omega2 + G_p) E) from "
                      "the surface energies of the particles and the "
                      "plastic dissipation (Gonzalez 2018 after Eq. 5); "
                      "false: the Fracture toughness entry.");
    declare_quantity(prm,
                     "Fracture toughness",
                     "0.48e6",
                     non_negative(),
                     "Pa m^1/2",
                     "Fracture toughness K_Ic of the solid bridge; 0 for "
                     "no bonding.");
    declare_quantity(prm,
                     "Plastic dissipation",
                     "0",
                     non_negative(),
                     "J/m^2",
                     "Plastic or other dissipation G_p added to the "
                     "surface energies when K_Ic is computed from energies.");
    prm.declare_entry("Regularized",
                      "true",
                      dealii::Patterns::Bool(),
                      "true: the continuous law of Gonzalez 2018 Eq. (4); "
                      "false: the unregularized Mesarovic-Johnson law of "
                      "Eq. (2), whose force jumps at the onset of "
                      "unloading.");
    declare_quantity(prm,
                     "Regularization parameter",
                     "0.01",
                     positive(),
                     "-",
                     "Regularization parameter xi_B > 0 of Eq. (4) "
                     "(Gonzalez 2018 recommends 0.01, Sec. 3.2).");
    prm.leave_subsection();
    coupling::declare_registered_laws(prm, false);
  }

  ContactPair
  make_contact_pair(dealii::ParameterHandler &prm)
  {
    const std::string law      = prm.get("Law");
    const std::string geometry = prm.get("Geometry");
    const bool        wall     = geometry == "sphere-wall";
    const Body        body1    = read_body(prm, "Particle 1");
    Body              body2    = read_body(prm, "Particle 2");
    if (wall)
      body2 = {dem::ElastoplasticMaterial::rigid_wall(
                 body1.material.plastic_exponent),
               dem::rigid,
               0.0};

    ContactPair pair;
    if (const auto *registered = dem::find_contact_law(law))
      pair = make_registered_pair(prm, *registered, body1, body2);
    else
      pair = make_bonded_pair(prm, body1, body2, wall);
    pair.geometry = geometry;
    return pair;
  }
} // namespace compax::cli

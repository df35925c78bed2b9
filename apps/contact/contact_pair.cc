#include "apps/contact/contact_pair.h"

#include "apps/cli/parameters.h"
#include "dem/contact/bonded_elastoplastic.h"
#include "dem/contact/contact_law_registry.h"
#include "dem/contact/hertz.h"
#include "dem/contact/multicontact_adhesive.h"
#include "dem/contact/nonlocal_hertz.h"
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
      Body body{get_particle_material(prm),
                get_particle_radius(prm),
                get_surface_energy(prm)};
      prm.leave_subsection();
      return body;
    }

    /// A law built from the radii and elastic constants of the two bodies,
    /// plus any law-specific arguments.
    template <typename Law, typename... Extra>
    std::unique_ptr<Law>
    elastic_law(const Body &body1, const Body &body2, const Extra &...extra)
    {
      return std::make_unique<Law>(Law::for_pair(body1.radius,
                                                 body1.material.youngs_modulus,
                                                 body1.material.poisson_ratio,
                                                 body2.radius,
                                                 body2.material.youngs_modulus,
                                                 body2.material.poisson_ratio,
                                                 extra...));
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

    /// Gonzalez & Cuitino 2012: the pair is the Tatara configuration, each
    /// sphere held by the opposite force at its far pole, so gamma_NL is
    /// found self-consistently at every overlap (Eqs. 9-11).
    ContactPair
    make_nonlocal_pair(const Body &body1, const Body &body2)
    {
      ContactPair pair;
      pair.law     = elastic_law<dem::NonlocalHertzLaw>(body1, body2);
      pair.context = [body1, body2](const double gamma) {
        dem::ContactContext context;
        if (gamma > 0.0)
          context.nonlocal_overlap
            = dem::solve_tatara_two_spheres(gamma,
                                            body1.radius,
                                            body1.material.youngs_modulus,
                                            body1.material.poisson_ratio,
                                            body2.radius,
                                            body2.material.youngs_modulus,
                                            body2.material.poisson_ratio)
                .nonlocal_overlap;
        return context;
      };
      return pair;
    }

    /// Giannis 2021: the particle pressure of both particles is a constant
    /// of the .prm (in a packing the particle solver supplies it).
    ContactPair
    make_multicontact_pair(dealii::ParameterHandler &prm,
                           const Body               &body1,
                           const Body               &body2)
    {
      prm.enter_subsection("Multi-contact");
      dem::MulticontactAdhesiveLaw::Parameters parameters;
      parameters.unloading_stiffness_ratio
        = prm.get_double("Unloading stiffness ratio");
      parameters.adhesion_stiffness_ratio
        = prm.get_double("Adhesion stiffness ratio");
      parameters.plasticity_depth       = prm.get_double("Plasticity depth");
      parameters.multicontact_prefactor = prm.get_double("Prefactor");
      parameters.pull_off_force         = prm.get_double("Pull-off force");
      parameters.poisson_ratio          = body1.material.poisson_ratio;
      const double compressive_stress
        = prm.get_double("Mean compressive stress");
      prm.leave_subsection();

      ContactPair pair;
      pair.law
        = elastic_law<dem::MulticontactAdhesiveLaw>(body1, body2, parameters);
      pair.context = [compressive_stress](double) {
        dem::ContactContext context;
        context.particle_pressure = -compressive_stress;
        return context;
      };
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
      prm.enter_subsection(law.subsection);
      dem::LawParameterValues values;
      for (const dem::LawParameter &p : law.parameters)
        values[p.name] = prm.get_double(p.name);
      prm.leave_subsection();
      ContactPair pair;
      pair.law = law.make(values, body1.radius, body2.radius);
      return pair;
    }

    /// Each registered law's subsection, as the law declares it.
    void
    declare_registered_laws(dealii::ParameterHandler &prm)
    {
      for (const dem::RegisteredContactLaw &law :
           dem::registered_contact_laws())
        {
          prm.enter_subsection(law.subsection);
          for (const dem::LawParameter &p : law.parameters)
            declare_quantity(
              prm,
              p.name,
              format_number(p.default_value),
              RealInterval(p.lower, p.lower_open, p.upper, p.upper_open),
              p.unit,
              p.documentation);
          prm.leave_subsection();
        }
    }

    /// "hertz|...": the built-in laws, then the registered ones.
    std::string
    law_names()
    {
      std::string names
        = "hertz|bonded-elastoplastic|nonlocal-hertz|multicontact-adhesive";
      for (const dem::RegisteredContactLaw &law :
           dem::registered_contact_laws())
        names += "|" + law.name;
      return names;
    }

    /// The registered laws' part of the Law documentation.
    std::string
    registered_law_documentation()
    {
      std::string text;
      for (const dem::RegisteredContactLaw &law :
           dem::registered_contact_laws())
        text += "; " + law.name + " (" + law.description + "; subsection "
                + law.subsection + ")";
      return text;
    }

    void
    declare_multicontact(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Multi-contact");
      declare_quantity(prm,
                       "Unloading stiffness ratio",
                       "120",
                       RealInterval(1.0, false, 1e12, false),
                       "-",
                       "k2/k1 >= 1: largest unloading/reloading stiffness "
                       "over the loading stiffness k1 = 4/3 E sqrt(R) "
                       "(Giannis 2021, Eq. 11; 120 in Table 3).");
      declare_quantity(prm,
                       "Adhesion stiffness ratio",
                       "0.5",
                       non_negative(),
                       "-",
                       "kc/k1 >= 0: adhesive branch stiffness (Eq. 10).");
      declare_quantity(prm,
                       "Plasticity depth",
                       "0.99",
                       non_negative(),
                       "-",
                       "phi_f: dimensionless plasticity depth of Eq. (12).");
      declare_quantity(prm,
                       "Prefactor",
                       "0",
                       non_negative(),
                       "-",
                       "beta: multi-contact prefactor of Eq. (13) (0: the "
                       "conventional, local model).");
      declare_quantity(prm,
                       "Pull-off force",
                       "0",
                       dealii::Patterns::Double(),
                       "N",
                       "F_0: constant pull-off force of Eq. (6).");
      declare_quantity(prm,
                       "Mean compressive stress",
                       "0",
                       dealii::Patterns::Double(),
                       "Pa",
                       "-(tr sigma_i + tr sigma_j)/3 of the two particles, "
                       "positive in compression: the P_ij of Eq. (13), held "
                       "constant along the history.");
      prm.leave_subsection();
    }
  } // namespace

  void
  declare_contact_pair(dealii::ParameterHandler &prm,
                       const ParticleDefaults   &defaults)
  {
    prm.declare_entry("Law",
                      "bonded-elastoplastic",
                      dealii::Patterns::Selection(law_names()),
                      "Contact law: hertz (elastic spheres); "
                      "bonded-elastoplastic (Gonzalez 2018, Eqs. 3-5, 13); "
                      "nonlocal-hertz (Gonzalez & Cuitino 2012, Eqs. 9-11, "
                      "in Tatara's configuration: each sphere held at its far "
                      "pole); multicontact-adhesive (Giannis 2021, Eqs. "
                      "6-14; subsection Multi-contact)"
                        + registered_law_documentation() + ".");
    prm.declare_entry("Geometry",
                      "sphere-wall",
                      dealii::Patterns::Selection("sphere-sphere|sphere-wall"),
                      "sphere-sphere: Particle 1 against Particle 2; "
                      "sphere-wall: Particle 1 against a rigid flat "
                      "(Particle 2 is then ignored).");
    for (const char *name : {"Particle 1", "Particle 2"})
      {
        prm.enter_subsection(name);
        declare_particle_material(prm, defaults);
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
    declare_multicontact(prm);
    declare_registered_laws(prm);
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
    if (law == "hertz")
      pair.law = elastic_law<dem::HertzLaw>(body1, body2);
    else if (law == "nonlocal-hertz")
      pair = make_nonlocal_pair(body1, body2);
    else if (law == "multicontact-adhesive")
      pair = make_multicontact_pair(prm, body1, body2);
    else if (const auto *registered = dem::find_contact_law(law))
      pair = make_registered_pair(prm, *registered, body1, body2);
    else
      pair = make_bonded_pair(prm, body1, body2, wall);
    pair.geometry = geometry;
    return pair;
  }
} // namespace compax::cli

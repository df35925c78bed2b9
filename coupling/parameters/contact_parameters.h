#pragma once

// The subsection Contact shared by `compax die` and `compax rve`: the
// contact law and the formulation, read and cross-checked, and the solver
// tolerances of the elastic laws.

#include "coupling/parameters/registered_law_parameters.h"
#include "dem/solver/contact_model.h"
#include "input/input_error.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace compax::coupling
{
  /// Contact/Contact law and Contact/Formulation.
  struct ContactChoice
  {
    std::string law;
    std::string formulation;
    /// The registered law of that name, or nullptr (bonded-elastoplastic,
    /// elastic).
    const dem::RegisteredContactLaw *registered = nullptr;
    /// Its parsed parameters.
    dem::LawParameterValues values;
  };

  /// Declares the subsection Contact: Contact law (bonded-elastoplastic,
  /// elastic, or a registered law without context, solved by the bonded
  /// law's particle solver) and Formulation (hertz or nonlocal), with the
  /// command's documentation of each, and the registered laws'
  /// subsections.
  inline void
  declare_contact_choice(dealii::ParameterHandler &prm,
                         const std::string        &law_documentation,
                         const std::string        &formulation_documentation)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Contact law",
      "bonded-elastoplastic",
      dealii::Patterns::Selection("bonded-elastoplastic|elastic"
                                  + registered_law_names(true)),
      law_documentation
        + " Registered laws, on the bonded law's particle solver with its "
          "Young's modulus and Poisson's ratio of Material (the plastic and "
          "Bonding entries are not used)"
        + registered_law_documentation(true) + ".");
    prm.declare_entry("Formulation",
                      "hertz",
                      dealii::Patterns::Selection("hertz|nonlocal"),
                      formulation_documentation);
    prm.leave_subsection();
    declare_registered_laws(prm, true);
  }

  /// Whether the registered law of @p choice is elastic (a law of elastic
  /// bodies that keeps no internal variables), so that the nonlocal
  /// formulation can be layered on it.
  inline bool
  registered_law_is_elastic(const ContactChoice &choice)
  {
    if (!choice.registered || choice.registered->context
        || !choice.registered->elastic_bodies)
      return false;
    // Any pair of bodies: which variables a law keeps does not depend on
    // them.
    const dem::ContactBodies unit_spheres{1.0, 1.0, 0.3, 1.0, 1.0, 0.3};
    return choice.registered->make(choice.values, unit_spheres)
      ->history_variables()
      .empty();
  }

  /// Reads the subsection Contact; rejects the nonlocal formulation on a
  /// law that is not elastic (InputError naming Contact/Formulation).
  inline ContactChoice
  get_contact_choice(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    const std::string law         = prm.get("Contact law");
    const std::string formulation = prm.get("Formulation");
    prm.leave_subsection();
    ContactChoice choice{law, formulation, dem::find_contact_law(law), {}};
    if (choice.registered)
      choice.values = get_registered_law_values(prm, *choice.registered);
    if (formulation == "nonlocal" && law != "elastic"
        && !registered_law_is_elastic(choice))
      input::reject_entry(
        "Contact/Formulation",
        formulation,
        "the nonlocal formulation (Gonzalez & Cuitino 2012) is a layer on "
        "an elastic law; it needs Contact/Contact law = elastic or a "
        "registered law of elastic bodies without internal variables "
        "(hertz; here: "
          + law
          + ", whose plastic bodies or internal variables, such as a "
            "plastic radius, a solid bridge or a largest overlap, are "
            "outside it)");
    return choice;
  }

  /// Whether the chosen contacts are solved as elastic spheres
  /// (NonlocalBedSystem): Contact law = elastic, or the nonlocal
  /// formulation on an elastic registered law.
  inline bool
  solved_as_elastic_spheres(const ContactChoice &choice)
  {
    return choice.law == "elastic" || choice.formulation == "nonlocal";
  }

  /// The local laws of the elastic-sphere solver: those of @p model when a
  /// registered law was chosen (after apply_contact_choice()), else none
  /// (Hertz's law of the materials).
  inline std::optional<dem::ContactModel>
  elastic_local_laws(const ContactChoice     &choice,
                     const dem::ContactModel &model)
  {
    if (!choice.registered)
      return std::nullopt;
    return model;
  }

  /// Every contact of @p model follows the chosen registered law, if one
  /// was chosen.
  inline void
  apply_contact_choice(const ContactChoice &choice, dem::ContactModel &model)
  {
    if (!choice.registered)
      return;
    try
      {
        model.use_registered_law(*choice.registered, choice.values);
      }
    catch (const std::invalid_argument &e)
      {
        input::reject_entry("Contact/Contact law", choice.law, e.what());
      }
  }

  /// The subsections that define a bed's contacts, for a checkpoint's
  /// "same state?" test: @p fixed and every registered law's subsection.
  inline std::vector<std::string>
  with_registered_law_subsections(std::vector<std::string> fixed)
  {
    for (const dem::RegisteredContactLaw &law : dem::registered_contact_laws())
      if (!law.parameters.empty() && !law.context)
        fixed.push_back(law.subsection);
    return fixed;
  }

  /// The Solver tolerances of the bonded law's equilibria carried over to
  /// the trust region of the elastic laws (`options.solver`), whose
  /// iteration limit is raised to theirs if lower.
  template <typename ElasticOptions, typename EquilibriumOptions>
  void
  set_elastic_solver_tolerances(ElasticOptions           &options,
                                const EquilibriumOptions &equilibrium)
  {
    options.solver.force_tolerance = equilibrium.force_tolerance;
    options.solver.step_tolerance  = equilibrium.step_tolerance;
    options.solver.max_iterations
      = std::max(options.solver.max_iterations, equilibrium.max_iterations);
  }
} // namespace compax::coupling

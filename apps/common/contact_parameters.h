#pragma once

// The subsection Contact shared by `compax die` and `compax rve`: the
// contact law and the formulation, read and cross-checked, and the solver
// tolerances of the elastic laws.

#include "apps/cli/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <string>

namespace compax::cli
{
  /// Contact/Contact law and Contact/Formulation.
  struct ContactChoice
  {
    std::string law;
    std::string formulation;
  };

  /// Declares the subsection Contact: Contact law (bonded-elastoplastic or
  /// elastic) and Formulation (hertz or nonlocal), with the command's
  /// documentation of each.
  inline void
  declare_contact_choice(dealii::ParameterHandler &prm,
                         const std::string        &law_documentation,
                         const std::string        &formulation_documentation)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Contact law",
                      "bonded-elastoplastic",
                      dealii::Patterns::Selection(
                        "bonded-elastoplastic|elastic"),
                      law_documentation);
    prm.declare_entry("Formulation",
                      "hertz",
                      dealii::Patterns::Selection("hertz|nonlocal"),
                      formulation_documentation);
    prm.leave_subsection();
  }

  /// Reads the subsection Contact; rejects the nonlocal formulation with a
  /// law other than elastic (InputError naming Contact/Formulation).
  inline ContactChoice
  get_contact_choice(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    const std::string law         = prm.get("Contact law");
    const std::string formulation = prm.get("Formulation");
    prm.leave_subsection();
    if (formulation == "nonlocal" && law != "elastic")
      reject_entry("Contact/Formulation",
                   formulation,
                   "the nonlocal formulation (Gonzalez & Cuitino 2012) is "
                   "for elastic frictionless spheres; it needs Contact/"
                   "Contact law = elastic (here: "
                     + law
                     + "; the bonded elasto-plastic law's plasticity and "
                       "solid bridges are outside it)");
    return {law, formulation};
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
} // namespace compax::cli

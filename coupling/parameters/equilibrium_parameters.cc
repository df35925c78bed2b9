#include "coupling/parameters/equilibrium_parameters.h"

#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"

#include <sstream>

namespace compax::coupling
{
  void
  declare_equilibrium_tolerances(dealii::ParameterHandler &prm,
                                 const std::string        &force_floor_note)
  {
    input::declare_quantity(
      prm,
      "Force tolerance",
      "1e-6",
      input::open(0.0, 1.0),
      "-",
      "Converged when the largest net force on a particle is "
      "below this times the mean contact force."
        + (force_floor_note.empty() ? std::string() : " " + force_floor_note));
    input::declare_quantity(
      prm,
      "Step tolerance",
      "1e-4",
      input::open(0.0, 1.0),
      "-",
      "... and the largest particle displacement of the last "
      "Newton step is below this times the mean radius.");
    prm.declare_entry("Maximum iterations",
                      "200",
                      dealii::Patterns::Integer(1, 1000000),
                      "Trust-region Newton iterations per load step (or "
                      "sub-step) before it is cut back, in [1, 1e6].");
    const dem::EquilibriumOptions defaults;
    std::ostringstream            stall;
    stall << "What relaxes the bed when the trust-region Newton stalls ("
          << defaults.stall_iterations
          << " iterations without a tenfold drop of the residual: a jammed "
             "bed rearranging), at fixed internal variables, to "
          << defaults.fire_tolerance << " of the mean contact force (at most "
          << defaults.fire_iterations
          << " iterations), before Newton goes on to the tolerances above: "
             "fire (FIRE) or lbfgs (L-BFGS, as Protocol/Unjammed "
             "equilibrium's). ";
    prm.declare_entry(
      "Stall relaxation",
      "fire",
      dealii::Patterns::Selection("fire|lbfgs"),
      stall.str()
        + "Both stop at the same tolerance; they may reach "
          "different equilibria of a rearranging bed, as any two solvers may. "
          "Measured on the Sec. 5 studies of the 6512-sphere die "
          "(doc/benchmarks.md, stop 51): lbfgs takes 17-23 % less time in the "
          "jammed compaction and the unloading and 12-28 % more in the "
          "ejection, about the same in all; the branches' punch pressures "
          "agree within 1 %, their elastic recoveries within 17-34 %.");
  }

  void
  get_equilibrium_tolerances(dealii::ParameterHandler &prm,
                             dem::EquilibriumOptions  &options)
  {
    options.force_tolerance = prm.get_double("Force tolerance");
    options.step_tolerance  = prm.get_double("Step tolerance");
    options.max_iterations  = prm.get_integer("Maximum iterations");
    options.stall_relaxation
      = prm.get("Stall relaxation") == "lbfgs"
          ? dem::EquilibriumOptions::StallRelaxation::lbfgs
          : dem::EquilibriumOptions::StallRelaxation::fire;
  }

  void
  declare_history_update(dealii::ParameterHandler &prm,
                         const std::string        &resolution_note)
  {
    prm.declare_entry(
      "History update",
      "resolved-forces",
      dealii::Patterns::Selection("resolved-forces|every-contact"),
      "Bonded path (Consolidation = none) only: the contacts Eq. 13 "
      "updates at a converged state. resolved-forces (default): a contact "
      "that loads plastically with a force not above the force resolution "
      "("
        + resolution_note
        + ") keeps its internal variables (no plastic radius, no bridge): "
          "the balanced loose states of an unjammed bed are force-free, and "
          "their left-over overlaps of the order of the solver tolerance "
          "are not taken as plastic deformation. every-contact: Eq. 13 "
          "applies at every positive overlap, however small its force, so "
          "the touching contacts of a loose bed grow plastic radii and "
          "bridges from the first converged state on (see "
          "doc/loose_regime.md for the measured difference).");
  }

  bool
  get_resolved_history(dealii::ParameterHandler &prm)
  {
    return prm.get("History update") == "resolved-forces";
  }
} // namespace compax::coupling

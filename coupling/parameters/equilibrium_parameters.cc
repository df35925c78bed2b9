#include "coupling/parameters/equilibrium_parameters.h"

#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"

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
  }

  void
  get_equilibrium_tolerances(dealii::ParameterHandler &prm,
                             dem::EquilibriumOptions  &options)
  {
    options.force_tolerance = prm.get_double("Force tolerance");
    options.step_tolerance  = prm.get_double("Step tolerance");
    options.max_iterations  = prm.get_integer("Maximum iterations");
  }
} // namespace compax::coupling

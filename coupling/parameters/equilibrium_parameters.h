#pragma once

#include "dem/solver/trust_region_newton.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace compax::coupling
{
  /// Declares, in the current subsection, the convergence entries of the
  /// particle equilibrium solver: Force tolerance, Step tolerance, Maximum
  /// iterations (per load step or sub-step). @p force_floor_note, if not
  /// empty, is appended to the documentation of Force tolerance.
  void
  declare_equilibrium_tolerances(dealii::ParameterHandler &prm,
                                 const std::string &force_floor_note = "");

  /// Reads them into @p options.
  void
  get_equilibrium_tolerances(dealii::ParameterHandler &prm,
                             dem::EquilibriumOptions  &options);
} // namespace compax::coupling

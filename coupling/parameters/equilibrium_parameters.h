#pragma once

#include "dem/solver/trust_region_newton.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace compax::coupling
{
  /// Declares, in the current subsection, the convergence entries of the
  /// particle equilibrium solver: Force tolerance, Step tolerance, Maximum
  /// iterations (per load step or sub-step), and Stall relaxation, the
  /// minimiser of a stalled Newton iteration. @p force_floor_note, if not
  /// empty, is appended to the documentation of Force tolerance.
  void
  declare_equilibrium_tolerances(dealii::ParameterHandler &prm,
                                 const std::string &force_floor_note = "");

  /// Reads them into @p options.
  void
  get_equilibrium_tolerances(dealii::ParameterHandler &prm,
                             dem::EquilibriumOptions  &options);

  /**
   * Declares, in the current subsection, `History update`: whether Eq. 13
   * of Gonzalez 2018 skips contacts whose force is below the force
   * resolution (the die's and the RVE's bonded path share it). @p
   * resolution_note says what the force resolution is where it is declared.
   */
  void
  declare_history_update(dealii::ParameterHandler &prm,
                         const std::string        &resolution_note);

  /// Reads it: true for resolved-forces.
  bool
  get_resolved_history(dealii::ParameterHandler &prm);
} // namespace compax::coupling

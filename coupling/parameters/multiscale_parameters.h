#pragma once

#include "fem/material_registry.h"

#include <deal.II/base/parameter_handler.h>

namespace compax::coupling
{
  /**
   * The materials of `compax tablet`'s Material/Model: the closed-form ones
   * of fem, then multiscale-database and multiscale-fe2, whose parameters
   * lie in the subsection Multiscale and which the application builds at
   * run time (they need MPI, the RVE and an output folder; no factory).
   */
  fem::MaterialRegistry
  tablet_materials();

  /**
   * Declares the subsection Multiscale of `compax tablet`: the RVE
   * (Material, Bonding, Packing of its particles), the database paths, the
   * RVE solver, and the FE2 options (Pool size, Tangent floor modulus,
   * Tangent floor stress, FE2 stress resolution).
   */
  void
  declare_multiscale_parameters(dealii::ParameterHandler &prm);

  /// Reads and checks the subsection (InputError naming the entry).
  void
  check_multiscale_parameters(dealii::ParameterHandler &prm);
} // namespace compax::coupling

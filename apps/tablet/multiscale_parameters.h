#pragma once

#include "fem/material_model.h"

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <memory>
#include <string>

namespace compax::cli
{
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

  /**
   * The particle-derived material of `Material/Model`:
   *  - multiscale-database: builds the RVE response database now (into
   *    `folder`/database/: database.csv, database.h5, dpc_table.csv/.png)
   *    and returns the Drucker-Prager Cap fitted to it;
   *  - multiscale-fe2: an RVE per quadrature point (coupling::RveMaterial)
   *    whose packings are consolidated along `compaction_axis`, the axial
   *    row of the tablet model's stress frame; the `points_per_cell`
   *    quadrature points of a cell start from the same packing.
   * Only a `write_files` caller writes the database files (rank 0 of an
   * MPI run). Throws std::runtime_error when the database's RVE does not
   * converge.
   */
  std::shared_ptr<fem::MaterialModel>
  make_multiscale_material(dealii::ParameterHandler    &prm,
                           const std::string           &model,
                           const std::filesystem::path &folder,
                           bool                         write_files,
                           unsigned int                 compaction_axis,
                           unsigned int                 points_per_cell);
} // namespace compax::cli

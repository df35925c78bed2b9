#pragma once

#include "coupling/rve_database_study.h"
#include "fem/material_model.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace compax::cli
{
  /**
   * The particle-derived material of `Material/Model`:
   *  - multiscale-database: the Drucker-Prager Cap fitted to the RVE
   *    response database, built now by rank 0 of @p comm, which alone
   *    prints its progress and writes it into `folder`/database/
   *    (database.csv, database.h5, dpc_table.csv/.png); every rank
   *    returns the same table
   *    (coupling::make_multiscale_database_material);
   *  - multiscale-fe2: an RVE per quadrature point (coupling::RveMaterial)
   *    whose packings are consolidated along `compaction_axis`, the axial
   *    row of the tablet model's stress frame; the `points_per_cell`
   *    quadrature points of a cell start from the same packing.
   * Collective on @p comm. Throws std::runtime_error on every rank when
   * the database's RVE does not converge. The database built, if any, is
   * also given in @p database (when not null, on rank 0).
   */
  std::shared_ptr<fem::MaterialModel>
  make_multiscale_material(
    dealii::ParameterHandler                        &prm,
    const std::string                               &model,
    const std::filesystem::path                     &folder,
    unsigned int                                     compaction_axis,
    unsigned int                                     points_per_cell,
    MPI_Comm                                         comm,
    std::optional<coupling::RveDatabaseStudyResult> *database = nullptr);
} // namespace compax::cli

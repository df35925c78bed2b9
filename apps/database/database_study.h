#pragma once

#include "apps/rve/rve_parameters.h"
#include "coupling/hdf5_archive.h"
#include "coupling/rve_database.h"
#include "fem/dpc_table.h"

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <string>
#include <vector>

namespace compax::cli
{
  /// An RVE response database to build: the cell and its paths.
  struct DatabaseStudy
  {
    RveCell                cell;
    coupling::DatabaseSpec spec;
  };

  /// Declares the subsection Paths (compaction, branch densities, shear
  /// probes).
  void
  declare_database_paths(dealii::ParameterHandler &prm);

  /// Declares Material, Bonding, Packing, Paths and Solver in the current
  /// subsection (`compax database` at the top level, `compax tablet` under
  /// Multiscale).
  void
  declare_database_parameters(dealii::ParameterHandler &prm);

  /// Reads them; `where` prefixes entry names in error messages (e.g.
  /// "Multiscale/"). Throws InputError.
  DatabaseStudy
  get_database_study(dealii::ParameterHandler &prm,
                     const std::string        &where = "");

  /// database.csv: every equilibrated state with p and q.
  void
  write_database_rows(const std::filesystem::path &folder,
                      const coupling::RveDatabase &database);

  /// database.h5 (an archive of kind "rve-database" with the canonical
  /// text of the @p parameters it was computed with): the same rows (with
  /// deformation gradient and parent row) and the branch summaries.
  void
  write_database_archive(const std::filesystem::path &folder,
                         const coupling::RveDatabase &database,
                         const std::string           &parameters);

  /// Writes the rows and branches of a database into an open archive
  /// (what database.h5 and the checkpoints hold).
  void
  write_database(coupling::Hdf5ArchiveWriter &archive,
                 const coupling::RveDatabase &database);

  /// Reads what write_database() wrote, exactly; throws on a malformed
  /// archive.
  coupling::RveDatabase
  read_database(const coupling::Hdf5ArchiveReader &archive);

  /// dpc_table.csv (the DpcTable format) and dpc_table.png.
  void
  write_dpc_table(const std::filesystem::path            &folder,
                  const std::vector<coupling::DpcFitRow> &rows);

  /// The fitted rows as the tablet model's DPC table (validated).
  fem::DpcTable
  to_dpc_table(const std::vector<coupling::DpcFitRow> &rows);
} // namespace compax::cli

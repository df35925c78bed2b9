#pragma once

#include "coupling/parameters/rve_parameters.h"
#include "coupling/rve_database.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace compax::coupling
{
  /// An RVE response database to build: the cell and its paths (of
  /// `compax database`, or of `compax tablet` under Multiscale).
  struct DatabaseSetup
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
  DatabaseSetup
  get_database_setup(dealii::ParameterHandler &prm,
                     const std::string        &where = "");

  /// Options of `compax database` only (not of the database a tablet
  /// builds): subsections Checkpoints and Validation.
  struct DatabaseRunOptions
  {
    int         stop_after_branches = 0;
    std::string resume_from;
    bool        held_out_packing = true;
  };

  void
  declare_database_run_options(dealii::ParameterHandler &prm);

  DatabaseRunOptions
  get_database_run_options(dealii::ParameterHandler &prm);

  /// The parameters that shape the database (all but Checkpoints and
  /// Validation), as canonical text: a checkpoint resumes only the same
  /// study.
  std::string
  database_fingerprint(const dealii::ParameterHandler &prm);
} // namespace compax::coupling

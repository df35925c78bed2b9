#pragma once

#include "apps/cli/command.h"
#include "apps/cli/input_error.h"
#include "coupling/rve_database_study.h"
#include "coupling/tablet_study.h"

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <memory>
#include <optional>

namespace compax::cli
{
  /// `compax tablet`: die compaction, unloading and ejection of a powder
  /// compact with the deal.II continuum model.
  std::unique_ptr<Command>
  make_tablet_command();

  /// What `compax tablet` computed and the exit code it returns.
  struct TabletRun
  {
    int code = success;
    /// The cycle, if the material was built (converged or not).
    std::optional<coupling::TabletStudyResult> result;
    /// The RVE response database of a multiscale-database material, if it
    /// was built.
    std::optional<coupling::RveDatabaseStudyResult> database;
  };

  /// The run of `compax tablet` with checked parameters @p prm: the study,
  /// its files in @p folder and its progress on std::cout, for a command
  /// that also needs the study's result (compax compare).
  TabletRun
  run_tablet(dealii::ParameterHandler    &prm,
             const std::filesystem::path &folder);
} // namespace compax::cli

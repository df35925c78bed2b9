#pragma once

#include "apps/cli/command.h"
#include "apps/cli/input_error.h"
#include "dem/die/die_study.h"

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <memory>

namespace compax::cli
{
  /// `compax die`: die compaction, unloading and ejection of a particle bed
  /// (Gonzalez 2018, Sec. 5).
  std::unique_ptr<Command>
  make_die_command();

  /// What `compax die` computed and the exit code it returns.
  struct DieRun
  {
    int                 code = success;
    dem::DieStudyResult result;
  };

  /// The run of `compax die` with checked parameters @p prm: the study,
  /// its files in @p folder and its progress on std::cout, for a command
  /// that also needs the study's result (compax compare).
  DieRun
  run_die(dealii::ParameterHandler &prm, const std::filesystem::path &folder);
} // namespace compax::cli

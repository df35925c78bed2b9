#pragma once

#include "apps/cli/command.h"
#include "apps/cli/input_error.h"
#include "apps/compare/compare_parameters.h"
#include "coupling/scale_comparison.h"

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace compax::cli
{
  /// A number as a .prm value, with enough digits that derived lengths
  /// and densities are passed on exactly enough.
  std::string
  number(double value);

  /// The parameters of @p command with @p settings applied and checked
  /// (InputError from the command, naming compare's own entry where it set
  /// the rejected one, else prefixed with the study's name).
  void
  prepare(const Command            &command,
          dealii::ParameterHandler &prm,
          const Settings           &settings,
          const std::string        &study);

  /// How one sub-study of compare went, for compare.md.
  struct StudyStatus
  {
    StudyStatus(std::string name, std::string folder)
        : name(std::move(name))
        , folder(std::move(folder))
    {
    }

    std::string name, folder;
    bool        ran  = false;
    int         code = success;
    std::string message;
    double      seconds = 0.0;
  };

  /**
   * Runs the sub-study @p command with @p settings in-process by @p run
   * (which keeps what it computed) in the folder @p status.folder of
   * @p parent (created here, with the parameters it ran with in
   * parameters.prm) and records in @p status that it ran, its exit code,
   * time and message: an exception of the study is reported in the
   * message and gives not_converged (bad input stays bad input).
   */
  void
  run_study(const Command                                           &command,
            const Settings                                          &settings,
            const std::filesystem::path                             &parent,
            const std::string                                       &study,
            StudyStatus                                             &status,
            const std::function<int(dealii::ParameterHandler &,
                                    const std::filesystem::path &)> &run);

  /// Settings of `compax tablet` for the same die and material as the
  /// particle study, filled with its deposited bed, in database or FE2
  /// mode, its database branching at @p branches.
  Settings
  tablet_settings(const CompareSetup            &c,
                  const coupling::DepositedFill &fill,
                  const std::vector<double>     &branches,
                  bool                           fe2);
} // namespace compax::cli

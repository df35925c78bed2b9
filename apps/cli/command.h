#pragma once

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <string>
#include <utility>

namespace compax::cli
{
  /// What `compax --help` and `compax <name> --help` say about a command.
  struct CommandInfo
  {
    /// The word typed after `compax`.
    std::string name;

    /// One line for `compax --help`.
    std::string summary;

    /// A paragraph for `compax <name> --help`: what the command computes,
    /// what it writes, and its built-in default case.
    std::string description;
  };

  /**
   * One subcommand of `compax` (contact, die, ...). A command declares its
   * documented parameters, may check relations between them, and runs on a
   * parsed ParameterHandler, writing into an output folder that the caller
   * created and publishes only if run() returns normally. Its name and help
   * texts are data, given once to the constructor.
   */
  class Command
  {
  public:
    explicit Command(CommandInfo info)
        : info(std::move(info))
    {
    }

    virtual ~Command() = default;

    /// The word typed after `compax`.
    const std::string &
    name() const
    {
      return info.name;
    }

    /// One line for `compax --help`.
    const std::string &
    summary() const
    {
      return info.summary;
    }

    /// The paragraph for `compax <name> --help`.
    const std::string &
    description() const
    {
      return info.description;
    }

    /// Declares every parameter with default, range pattern and
    /// documentation naming its unit.
    virtual void
    declare_parameters(dealii::ParameterHandler &prm) const = 0;

    /**
     * Checks that need more than one entry, or ranges that deal.II's
     * patterns cannot express. Throws InputError naming the entry, its
     * value and the allowed range. Runs before any output is created.
     */
    virtual void
    check_parameters(dealii::ParameterHandler &) const
    {
    }

    /// Runs the study; returns an ExitCode.
    virtual int
    run(dealii::ParameterHandler    &prm,
        const std::filesystem::path &output_directory) const = 0;

  private:
    CommandInfo info;
  };
} // namespace compax::cli

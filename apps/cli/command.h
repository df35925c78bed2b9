#pragma once

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <string>

namespace compax::cli
{
  /**
   * One subcommand of `compax` (contact, die, ...). A command declares its
   * documented parameters, may check relations between them, and runs on a
   * parsed ParameterHandler, writing into an output folder that the caller
   * created and publishes only if run() returns normally.
   */
  class Command
  {
  public:
    virtual ~Command() = default;

    /// The word typed after `compax`.
    virtual std::string
    name() const = 0;

    /// One line for `compax --help`.
    virtual std::string
    summary() const = 0;

    /// A paragraph for `compax <name> --help`: what the command computes,
    /// what it writes, and its built-in default case.
    virtual std::string
    description() const = 0;

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
  };
} // namespace compax::cli

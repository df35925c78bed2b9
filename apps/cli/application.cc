#include "apps/cli/application.h"

#include "apps/cli/commands.h"
#include "apps/cli/input_error.h"
#include "apps/cli/output_directory.h"
#include "apps/cli/parameters.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace compax::cli
{
  namespace
  {
    constexpr const char *version = "0.1.0";

    /// The output folder rules, for --help.
    constexpr const char *output_rules_text
      = "OUTDIR (default <command>-output) is written only when the run "
        "ends (exit 0 or 3);\n"
        "until then the run works in .<OUTDIR>.partial-<pid> next to it and "
        "holds the\n"
        "lock .<OUTDIR>.lock, so a second run into the same OUTDIR is "
        "refused. compax\n"
        "never deletes or overwrites what it did not write: an existing "
        "OUTDIR must be\n"
        "empty, or hold an earlier compax output (marker file .compax-output, "
        "nothing\n"
        "else) and then needs --overwrite. Refused always: '.', '..', a "
        "folder holding\n"
        "the working folder or the .prm, the home folder, '/', an existing "
        "file.\n";

    /// What the words after the command name ask for.
    struct Invocation
    {
      bool                                 help             = false;
      bool                                 print_parameters = false;
      bool                                 check_only       = false;
      bool                                 overwrite        = false;
      std::optional<std::filesystem::path> parameter_file;
      std::optional<std::filesystem::path> output;
    };

    void
    print_usage(std::ostream                                &out,
                const std::vector<std::unique_ptr<Command>> &commands)
    {
      out << "compax " << version
          << " - multiscale simulation of pharmaceutical tablet die "
             "compaction\n\n"
             "Usage:\n"
             "  compax <command> [file.prm] [-o OUTDIR] [--overwrite]\n"
             "                                            run a study (no "
             "file: its built-in default case)\n"
             "  compax <command> --print-parameters       print the "
             "documented defaults as a valid .prm\n"
             "  compax <command> [file.prm] --check       validate the "
             "parameters, run nothing\n"
             "  compax <command> --help                   describe a "
             "command\n"
             "  compax --help | --version\n\n"
             "Commands:\n";
      for (const auto &command : commands)
        out << "  " << command->name()
            << std::string(
                 12 - std::min<std::size_t>(11, command->name().size()), ' ')
            << command->summary() << '\n';
      out << "\n"
          << output_rules_text
          << "\nExit codes: 0 success, 1 internal error, 2 bad input (no "
             "output written),\n3 solver did not converge (last good state "
             "kept in OUTDIR).\nAll quantities are in SI units.\n";
    }

    Invocation
    parse_arguments(const std::string              &command,
                    const std::vector<std::string> &words)
    {
      Invocation call;
      for (std::size_t i = 0; i < words.size(); ++i)
        {
          const std::string &word = words[i];
          if (word == "--help" || word == "-h")
            call.help = true;
          else if (word == "--print-parameters")
            call.print_parameters = true;
          else if (word == "--check")
            call.check_only = true;
          else if (word == "--overwrite")
            call.overwrite = true;
          else if (word == "-o" || word == "--output")
            {
              if (i + 1 == words.size())
                throw InputError("option '" + word
                                 + "' needs a folder name after it");
              const std::string &value = words[++i];
              if (call.output)
                throw InputError("option '" + word + "' given twice (OUTDIR '"
                                 + call.output->string() + "' and '" + value
                                 + "'); give one output folder");
              if (value.empty())
                throw InputError("option '" + word
                                 + "' needs a folder name; got an empty one");
              if (value[0] == '-')
                throw InputError("option '" + word
                                 + "' needs a folder name after it; got the "
                                   "option '"
                                 + value
                                 + "' (a folder whose name starts with '-' "
                                   "can be given as ./"
                                 + value + ")");
              call.output = value;
            }
          else if (!word.empty() && word[0] == '-')
            throw InputError("unknown option '" + word + "' for 'compax "
                             + command + "' (see 'compax " + command
                             + " --help')");
          else if (call.parameter_file)
            throw InputError("only one parameter file may be given; got '"
                             + call.parameter_file->string() + "' and '" + word
                             + "'");
          else
            call.parameter_file = word;
        }
      return call;
    }

    /**
     * MPI (deal.II, Trilinos, the parallel HDF5 of checkpoints) starts only
     * when a study runs, so that --help and --check answer at once; one
     * thread per rank. It finalizes when the program exits.
     */
    void
    start_mpi(int &argc, char **&argv)
    {
      static std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
      if (!mpi)
        mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc,
                                                                         argv,
                                                                         1);
    }

    /**
     * Whether this process reports an internal error: under mpirun every
     * rank meets the same one, so rank 0 alone says it (each rank still
     * exits non-zero); without MPI, the one process.
     */
    bool
    reports_internal_errors()
    {
      return !dealii::Utilities::MPI::job_supports_mpi()
             || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    }

    int
    run_command(const Command                  &command,
                const std::vector<std::string> &words,
                int                            &argc,
                char                         **&argv)
    {
      const Invocation call = parse_arguments(command.name(), words);

      dealii::ParameterHandler prm;
      command.declare_parameters(prm);

      if (call.help)
        {
          std::cout << "compax " << command.name() << " - " << command.summary()
                    << "\n\n"
                    << command.description() << "\n\nUsage: compax "
                    << command.name()
                    << " [file.prm] [-o OUTDIR] [--overwrite] | [file.prm] "
                       "--check | --print-parameters | --help\nDefault "
                       "OUTDIR: "
                    << command.name()
                    << "-output. Parameters (documented, with units): "
                       "compax "
                    << command.name() << " --print-parameters\n\n"
                    << output_rules_text;
          return success;
        }
      if (call.print_parameters)
        {
          print_documented_parameters(prm, std::cout);
          return success;
        }

      if (call.parameter_file)
        parse_parameter_file(prm, *call.parameter_file);
      command.check_parameters(prm);
      OutputRules rules;
      rules.overwrite = call.overwrite;
      rules.command   = command.name();
      rules.version   = version;
      if (call.parameter_file)
        rules.inputs.push_back(*call.parameter_file);
      const std::filesystem::path outdir
        = call.output.value_or(command.name() + "-output");
      if (call.check_only)
        {
          if (call.output)
            check_output_directory(outdir, rules);
          std::cout << "compax " << command.name() << ": parameters are valid"
                    << '\n';
          return success;
        }

      start_mpi(argc, argv);
      OutputDirectory output(outdir, rules);
      const bool      root
        = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      if (root)
        std::ofstream(output.staging() / "parameters.prm") << [&] {
          std::ostringstream used;
          prm.print_parameters(
            used,
            dealii::ParameterHandler::ShortPRM
              | dealii::ParameterHandler::KeepDeclarationOrder);
          return used.str();
        }();

      const int code = command.run(prm, output.staging());
      if (code == success)
        {
          output.publish();
          if (root)
            std::cout << "Results in " << output.final().string() << '\n';
        }
      else if (code == not_converged)
        {
          output.publish();
          if (root)
            std::cerr << "compax " << command.name()
                      << ": stopped without convergence; the last good state "
                         "is in "
                      << output.final().string() << '\n';
        }
      return code;
    }
  } // namespace

  int
  run_application(int argc, char **argv)
  {
    const auto               commands = all_commands();
    std::vector<std::string> words(argv + 1, argv + argc);
    std::string              context = "compax";
    try
      {
        if (words.empty() || words[0] == "--help" || words[0] == "-h")
          {
            print_usage(std::cout, commands);
            return words.empty() ? bad_input : success;
          }
        if (words[0] == "--version")
          {
            std::cout << "compax " << version << '\n';
            return success;
          }
        for (const auto &command : commands)
          if (command->name() == words[0])
            {
              context += " " + command->name();
              return run_command(*command,
                                 {words.begin() + 1, words.end()},
                                 argc,
                                 argv);
            }
        throw InputError("unknown command '" + words[0]
                         + "' (see 'compax --help')");
      }
    catch (const InputError &e)
      {
        std::cerr << context << ": error: " << e.what() << '\n';
        return bad_input;
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        if (reports_internal_errors())
          std::cerr << context << ": internal error: " << info.str() << '\n';
        return failure;
      }
    catch (const std::exception &e)
      {
        if (reports_internal_errors())
          std::cerr << context << ": internal error: " << e.what() << '\n';
        return failure;
      }
  }
} // namespace compax::cli

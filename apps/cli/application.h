#pragma once

namespace compax::cli
{
  /**
   * The whole `compax` program: parses the command line, finds the
   * subcommand, reads and checks its parameters, runs it in a staging
   * output folder and publishes the folder on success. Returns the exit
   * code (see ExitCode); never throws.
   */
  int
  run_application(int argc, char **argv);
} // namespace compax::cli

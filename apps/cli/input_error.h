#pragma once

#include <stdexcept>
#include <string>

namespace compax::cli
{
  /**
   * Bad input from the user: an unknown or malformed parameter, a value out
   * of range, a missing file. The program prints what() alone and exits
   * with code 2, leaving no output folder behind.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// The exit codes of `compax`, documented in `compax --help`.
  enum ExitCode : int
  {
    success       = 0,
    failure       = 1, ///< an unexpected internal error
    bad_input     = 2, ///< InputError
    not_converged = 3  ///< a solver gave up; the last good state was kept
  };
} // namespace compax::cli

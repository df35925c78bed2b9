#pragma once

#include "input/input_error.h"

namespace compax::cli
{
  using input::InputError;

  /// The exit codes of `compax`, documented in `compax --help`.
  enum ExitCode : int
  {
    success       = 0,
    failure       = 1, ///< an unexpected internal error
    bad_input     = 2, ///< InputError
    not_converged = 3  ///< a solver gave up; the last good state was kept
  };
} // namespace compax::cli

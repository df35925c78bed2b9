#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax jamming`: where a deposit jams in the die, bonded path against
  /// frozen-history consolidation, with and without solid bridges
  /// (Gonzalez 2018, Sec. 5.1, Eq. 14).
  std::unique_ptr<Command>
  make_jamming_command();
} // namespace compax::cli

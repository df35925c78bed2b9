#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax compare`: the particle die simulation, the RVE database and
  /// the multiscale tablet (database and FE2 modes) of one die and
  /// material, side by side (issue #6).
  std::unique_ptr<Command>
  make_compare_command();
} // namespace compax::cli

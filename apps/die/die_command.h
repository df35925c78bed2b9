#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax die`: die compaction, unloading and ejection of a particle bed
  /// (Gonzalez 2018, Sec. 5).
  std::unique_ptr<Command>
  make_die_command();
} // namespace compax::cli

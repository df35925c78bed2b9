#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax tablet`: die compaction, unloading and ejection of a powder
  /// compact with the deal.II continuum model.
  std::unique_ptr<Command>
  make_tablet_command();
} // namespace compax::cli

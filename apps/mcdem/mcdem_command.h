#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax mcdem`: explicit multi-contact DEM compaction of a periodic
  /// RVE (Giannis 2021).
  std::unique_ptr<Command>
  make_mcdem_command();
} // namespace compax::cli

#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax database`: an RVE response database and the Drucker-Prager
  /// Cap fitted to it (the continuum law of the tablet model).
  std::unique_ptr<Command>
  make_database_command();
} // namespace compax::cli

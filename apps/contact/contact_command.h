#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax contact`: one contact pair along a prescribed overlap history.
  std::unique_ptr<Command>
  make_contact_command();
} // namespace compax::cli

#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax crystal`: the granular crystals of Gonzalez & Cuitino 2012,
  /// Sec. 4.1, with Hertz theory and the nonlocal contact formulation.
  std::unique_ptr<Command>
  make_crystal_command();
} // namespace compax::cli

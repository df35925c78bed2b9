#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax bed`: the disordered two-material bed of Gonzalez & Cuitino
  /// 2012, Sec. 4.2, compacted in a square die under Hertz theory and under
  /// the nonlocal contact formulation.
  std::unique_ptr<Command>
  make_bed_command();
} // namespace compax::cli

#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax rve`: a periodic cell of bonded elasto-plastic spheres along a
  /// macroscopic strain path, with homogenized stress, consistent tangent
  /// and elastic moduli (issue #4), and RVE-size studies.
  std::unique_ptr<Command>
  make_rve_command();
} // namespace compax::cli

#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax calibrate`: fits k2/k1, kc/k1 and beta of the multi-contact
  /// law to a stress-strain curve by maximizing R^2 (Giannis 2021 §4.1.1).
  std::unique_ptr<Command>
  make_calibrate_command();
} // namespace compax::cli

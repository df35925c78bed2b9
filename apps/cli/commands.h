#pragma once

#include "apps/cli/command.h"

#include <memory>
#include <vector>

namespace compax::cli
{
  /// Every subcommand of `compax`, in the order `compax --help` lists them.
  std::vector<std::unique_ptr<Command>>
  all_commands();
} // namespace compax::cli

#pragma once

#include "apps/cli/command.h"

#include <memory>

namespace compax::cli
{
  /// `compax docs`: the parameter reference of every command as Markdown,
  /// generated from the declarations the commands parse with.
  std::unique_ptr<Command>
  make_docs_command();
} // namespace compax::cli

#pragma once

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <string>

namespace compax::input
{
  /**
   * Parses a .prm file into prm. A missing file, an unknown entry, a
   * malformed or out-of-range value all become one InputError whose message
   * names the file, line, entry, value and allowed range.
   */
  void
  parse_parameter_file(dealii::ParameterHandler    &prm,
                       const std::filesystem::path &file);

  /// Folder of the parameter file parsed last (absolute), empty before
  /// any: relative file names inside a .prm are relative to it.
  std::filesystem::path
  parameter_file_directory();

  /// A file named in a .prm: absolute as given, relative to the .prm's
  /// folder otherwise (the current folder when no file was parsed).
  std::filesystem::path
  resolve_input_path(const std::string &path);

  /**
   * Throws an InputError naming the first entry with a real-number pattern
   * whose value (or an item of its list) under- or overflows a double
   * (e.g. 1e-320): deal.II's patterns accept such values, but reading them
   * fails. Called by parse_parameter_file().
   */
  void
  check_representable_numbers(const dealii::ParameterHandler &prm);
} // namespace compax::input

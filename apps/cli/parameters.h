#pragma once

#include "input/canonical_parameters.h"
#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_documentation.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"

/**
 * @file
 * The commands declare, parse and document their parameters with the
 * library's input vocabulary (compax::input, which the libraries' own
 * declarations use too), named here without the namespace.
 */

namespace compax::cli
{
  using input::canonical_parameters;
  using input::check_representable_numbers;
  using input::closed;
  using input::declare_quantity;
  using input::format_number;
  using input::get_real_list;
  using input::non_negative;
  using input::open;
  using input::parameter_file_directory;
  using input::parse_parameter_file;
  using input::positive;
  using input::print_documented_parameters;
  using input::RealInterval;
  using input::reject_entry;
  using input::resolve_input_path;
  using input::write_parameters_markdown;
} // namespace compax::cli

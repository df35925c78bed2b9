#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <string>
#include <vector>

/**
 * @file
 * How compax declares and reads an entry: every entry's documentation names
 * its unit and allowed values, so that `--print-parameters`, `compax docs`
 * and the error messages all show them.
 */

namespace compax::input
{
  /**
   * Declares an entry whose documentation names its unit, e.g.
   * declare_quantity(prm, "Young's modulus", "5e9", positive(), "Pa",
   * "Young's modulus E of the particle material.").
   */
  void
  declare_quantity(dealii::ParameterHandler            &prm,
                   const std::string                   &name,
                   const std::string                   &default_value,
                   const dealii::Patterns::PatternBase &pattern,
                   const std::string                   &unit,
                   const std::string                   &documentation);

  /// A comma-separated list of reals read from an entry declared with
  /// Patterns::List(Patterns::Double()).
  std::vector<double>
  get_real_list(dealii::ParameterHandler &prm, const std::string &name);

  /// A number as a .prm or message shows it ("5e+09", "0.25").
  std::string
  format_number(double value);
} // namespace compax::input

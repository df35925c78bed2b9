#pragma once

#include <limits>
#include <map>
#include <string>
#include <vector>

/**
 * @file
 * What a contact law declares of its own parameters, without deal.II: the
 * command line turns each declaration into a documented, range-checked
 * entry of its subsection and hands the parsed values back by name.
 */

namespace compax::dem
{
  /// One real parameter of a contact law, in its unit, with the interval
  /// the law accepts.
  struct LawParameter
  {
    std::string name;
    double      default_value = 0.0;
    double      lower         = -std::numeric_limits<double>::infinity();
    bool        lower_open    = true;
    double      upper         = std::numeric_limits<double>::infinity();
    bool        upper_open    = true;
    /// Unit as in the parameter documentation ("N/m", "-").
    std::string unit;
    std::string documentation;
  };

  /// Parsed values of a law's parameters, by LawParameter::name.
  using LawParameterValues = std::map<std::string, double>;
} // namespace compax::dem

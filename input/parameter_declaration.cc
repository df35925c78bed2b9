#include "input/parameter_declaration.h"

#include "input/real_interval.h"

#include <deal.II/base/utilities.h>

#include <sstream>

namespace compax::input
{
  void
  declare_quantity(dealii::ParameterHandler            &prm,
                   const std::string                   &name,
                   const std::string                   &default_value,
                   const dealii::Patterns::PatternBase &pattern,
                   const std::string                   &unit,
                   const std::string                   &documentation)
  {
    std::string text = documentation + " Unit: " + unit + ".";
    if (const auto *interval = dynamic_cast<const RealInterval *>(&pattern))
      text += " Allowed: " + interval->interval() + ".";
    prm.declare_entry(name, default_value, pattern, text);
  }

  std::vector<double>
  get_real_list(dealii::ParameterHandler &prm, const std::string &name)
  {
    std::vector<double> values;
    for (const auto &item :
         dealii::Utilities::split_string_list(prm.get(name), ','))
      values.push_back(dealii::Utilities::string_to_double(item));
    return values;
  }

  std::string
  format_number(const double value)
  {
    std::ostringstream out;
    out << value;
    return out.str();
  }
} // namespace compax::input

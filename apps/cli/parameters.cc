#include "apps/cli/parameters.h"

#include "apps/cli/input_error.h"

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    std::string
    format_bound(const double value)
    {
      if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
      std::ostringstream out;
      out << value;
      return out.str();
    }

    /// deal.II's messages span several indented lines; users get one line.
    std::string
    one_line(const std::string &text)
    {
      std::string result;
      bool        space = false;
      for (const char c : text)
        if (std::isspace(static_cast<unsigned char>(c)))
          space = !result.empty();
        else
          {
            if (space)
              result += ' ';
            result += c;
            space = false;
          }
      return result;
    }
  } // namespace

  RealInterval::RealInterval(const double lower,
                             const bool   lower_open,
                             const double upper,
                             const bool   upper_open)
      : lower(lower)
      , upper(upper)
      , lower_open(lower_open)
      , upper_open(upper_open)
  {
  }

  bool
  RealInterval::match(const std::string &text) const
  {
    std::istringstream in(text);
    double             value;
    if (!(in >> value))
      return false;
    std::string rest;
    if (in >> rest)
      return false;
    if (!std::isfinite(value))
      return false;
    const bool above = lower_open ? value > lower : value >= lower;
    const bool below = upper_open ? value < upper : value <= upper;
    return above && below;
  }

  std::string
  RealInterval::interval() const
  {
    return std::string(lower_open ? "(" : "[") + format_bound(lower) + ", "
           + format_bound(upper) + (upper_open ? ")" : "]");
  }

  std::string
  RealInterval::description(const OutputStyle style) const
  {
    if (style == Machine)
      return "[Real number in " + interval() + "]";
    return "A real number in " + interval();
  }

  std::unique_ptr<dealii::Patterns::PatternBase>
  RealInterval::clone() const
  {
    return std::make_unique<RealInterval>(*this);
  }

  RealInterval
  positive()
  {
    return {0.0, true, std::numeric_limits<double>::infinity(), true};
  }

  RealInterval
  non_negative()
  {
    return {0.0, false, std::numeric_limits<double>::infinity(), true};
  }

  RealInterval
  closed(const double lower, const double upper)
  {
    return {lower, false, upper, false};
  }

  RealInterval
  open(const double lower, const double upper)
  {
    return {lower, true, upper, true};
  }

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

  namespace
  {
    std::filesystem::path last_parameter_file_directory;
  }

  std::filesystem::path
  parameter_file_directory()
  {
    return last_parameter_file_directory;
  }

  std::filesystem::path
  resolve_input_path(const std::string &path)
  {
    const std::filesystem::path p(path);
    if (p.empty() || p.is_absolute())
      return p;
    return parameter_file_directory() / p;
  }

  void
  parse_parameter_file(dealii::ParameterHandler    &prm,
                       const std::filesystem::path &file)
  {
    if (!std::filesystem::is_regular_file(file))
      throw InputError("parameter file '" + file.string()
                       + "' does not exist or is not a regular file");
    last_parameter_file_directory
      = std::filesystem::absolute(file).parent_path();
    try
      {
        prm.parse_input(file.string(), "", false, false);
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        throw InputError("in '" + file.string() + "': " + one_line(info.str()));
      }
    catch (const std::exception &e)
      {
        throw InputError("in '" + file.string() + "': " + one_line(e.what()));
      }
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

  void
  reject_entry(const std::string &name,
               const std::string &value,
               const std::string &message)
  {
    throw InputError("entry '" + name + "' = " + value + ": " + message);
  }
} // namespace compax::cli

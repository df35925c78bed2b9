#include "input/real_interval.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace compax::input
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
    // strtod as deal.II's get_double(), which refuses what under- or
    // overflows a double (1e-320, 1e999).
    const char *begin = text.c_str();
    while (std::isspace(static_cast<unsigned char>(*begin)))
      ++begin;
    char *end          = nullptr;
    errno              = 0;
    const double value = std::strtod(begin, &end);
    if (end == begin || errno == ERANGE)
      return false;
    while (std::isspace(static_cast<unsigned char>(*end)))
      ++end;
    if (*end != '\0')
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
} // namespace compax::input

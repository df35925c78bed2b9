#include "apps/cli/parameters.h"

#include "apps/cli/input_error.h"
#include "coupling/hdf5_archive.h"

#include <deal.II/base/exceptions.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
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
    std::error_code error;
    const auto      status = std::filesystem::status(file, error);
    if (!std::filesystem::exists(status))
      throw InputError("parameter file '" + file.string() + "' does not exist");
    if (std::filesystem::is_directory(status))
      throw InputError("parameter file '" + file.string()
                       + "' is a folder, not a file");
    if (!std::filesystem::is_regular_file(status))
      throw InputError("parameter file '" + file.string()
                       + "' is not a regular file");
    if (std::ifstream probe(file); !probe)
      throw InputError("parameter file '" + file.string() + "' cannot be read ("
                       + std::strerror(errno) + ")");
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

  namespace
  {
    std::string
    trimmed(const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t");
      if (first == std::string::npos)
        return {};
      return text.substr(first, text.find_last_not_of(" \t") - first + 1);
    }

    /// A number in its shortest form that reads back exactly; other text
    /// trimmed, yes/no as true/false.
    std::string
    canonical_item(const std::string &item)
    {
      const std::string t = trimmed(item);
      if (t == "yes")
        return "true";
      if (t == "no")
        return "false";
      char        *end   = nullptr;
      const double value = std::strtod(t.c_str(), &end);
      if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(value))
        return t;
      char buffer[64];
      if (value == std::floor(value) && std::abs(value) < 1e15)
        {
          std::snprintf(buffer, sizeof(buffer), "%.0f", value);
          return buffer;
        }
      for (int digits = 1; digits <= 17; ++digits)
        {
          std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
          if (std::strtod(buffer, nullptr) == value)
            break;
        }
      return buffer;
    }

    bool
    lies_below(const std::string &path, const std::string &prefix)
    {
      return path == prefix
             || (path.size() > prefix.size() && path[prefix.size()] == '/'
                 && path.compare(0, prefix.size(), prefix) == 0);
    }
  } // namespace

  std::string
  canonical_parameters(const dealii::ParameterHandler &prm,
                       const std::vector<std::string> &include,
                       const std::vector<std::string> &exclude,
                       const std::vector<std::string> &files)
  {
    std::ostringstream all;
    prm.print_parameters(all,
                         dealii::ParameterHandler::ShortPRM
                           | dealii::ParameterHandler::KeepDeclarationOrder);
    std::istringstream       lines(all.str());
    std::vector<std::string> sections;
    std::string              text;
    const auto               matches
      = [](const std::string &path, const std::vector<std::string> &list) {
          for (const std::string &p : list)
            if (lies_below(path, p))
              return true;
          return false;
        };
    for (std::string line; std::getline(lines, line);)
      {
        const std::string t = trimmed(line);
        if (t.rfind("subsection ", 0) == 0)
          sections.push_back(trimmed(t.substr(11)));
        else if (t == "end" && !sections.empty())
          sections.pop_back();
        else if (t.rfind("set ", 0) == 0)
          {
            const auto  eq   = t.find('=');
            std::string path = "";
            for (const std::string &s : sections)
              path += s + "/";
            path += trimmed(t.substr(4, eq - 4));
            const std::string value
              = eq == std::string::npos ? "" : trimmed(t.substr(eq + 1));
            if ((!include.empty() && !matches(path, include))
                || matches(path, exclude))
              continue;
            std::string canonical;
            if (matches(path, files))
              {
                const std::string hash
                  = value.empty()
                      ? std::string()
                      : coupling::file_hash(resolve_input_path(value).string());
                canonical = value.empty()  ? ""
                            : hash.empty() ? "missing"
                                           : "content " + hash;
              }
            else
              {
                std::istringstream items(value);
                bool               first = true;
                for (std::string item; std::getline(items, item, ',');)
                  {
                    canonical += (first ? "" : ", ") + canonical_item(item);
                    first = false;
                  }
              }
            text += path + " = " + canonical + "\n";
          }
      }
    return text;
  }

  namespace
  {
    /// ParameterHandler's mangling of names in its property tree.
    std::string
    mangled(const std::string &name)
    {
      static const char digits[] = "0123456789abcdef";
      std::string       result;
      for (const unsigned char c : name)
        if (std::isalnum(c))
          result += static_cast<char>(c);
        else
          {
            result += '_';
            result += digits[c / 16];
            result += digits[c % 16];
          }
      return result;
    }

    std::string
    bound(const std::string &text)
    {
      if (text == "2147483647" || text == "4294967295" || text == "MAX_DOUBLE"
          || text == "1.79769e+308")
        return "inf";
      if (text == "-2147483648" || text == "-MAX_DOUBLE"
          || text == "-1.79769e+308")
        return "-inf";
      return text;
    }

    /// The allowed values of a pattern's machine description, in words;
    /// empty for anything.
    std::string
    allowed(const std::string &d)
    {
      const auto range = [&](const std::string &prefix) -> std::string {
        const auto dots = d.find("...");
        const auto end  = d.find(" (inclusive)");
        if (d.rfind(prefix, 0) != 0 || dots == std::string::npos
            || end == std::string::npos)
          return {};
        const std::string lo
          = bound(d.substr(prefix.size(), dots - prefix.size()));
        const std::string hi = bound(d.substr(dots + 3, end - dots - 3));
        return (lo == "-inf" ? "(" : "[") + lo + ", " + hi
               + (hi == "inf" ? ")" : "]");
      };
      if (d.rfind("[Integer range ", 0) == 0)
        return "an integer in " + range("[Integer range ");
      if (d == "[Integer]")
        return "an integer";
      if (d.rfind("[Double ", 0) == 0)
        return "a number in " + range("[Double ");
      if (d == "[Bool]")
        return "true or false";
      if (d == "[Anything]")
        return "any text";
      if (d.rfind("[Selection ", 0) == 0)
        {
          std::string options = d.substr(11, d.size() - 12);
          while (!options.empty() && options.back() == ' ')
            options.pop_back();
          return "one of " + options;
        }
      if (d.rfind("[List of <", 0) == 0)
        {
          const auto close = d.rfind("> of length ");
          if (close == std::string::npos)
            return {};
          const std::string inner  = allowed(d.substr(10, close - 10));
          const std::string length = d.substr(close + 12);
          const auto        dots   = length.find("...");
          const auto        end    = length.find(" (inclusive)");
          std::string       count;
          if (dots != std::string::npos && end != std::string::npos)
            {
              const std::string lo = length.substr(0, dots);
              const std::string hi
                = bound(length.substr(dots + 3, end - dots - 3));
              count = hi == "inf" ? lo + " or more" : lo + " to " + hi;
            }
          return "a comma-separated list of " + count + " values, each "
                 + (inner.empty() ? "any text" : inner);
        }
      return {};
    }
  } // namespace

  void
  print_documented_parameters(const dealii::ParameterHandler &prm,
                              std::ostream                   &out)
  {
    std::ostringstream text, json;
    prm.print_parameters(text,
                         dealii::ParameterHandler::PRM
                           | dealii::ParameterHandler::KeepDeclarationOrder);
    prm.print_parameters(json,
                         dealii::ParameterHandler::JSON
                           | dealii::ParameterHandler::KeepDeclarationOrder);
    boost::property_tree::ptree tree;
    try
      {
        std::istringstream in(json.str());
        boost::property_tree::read_json(in, tree);
      }
    catch (const std::exception &)
      {
        out << text.str();
        return;
      }
    std::istringstream       lines(text.str());
    std::vector<std::string> sections;
    bool                     stated = false; // the comment names the range
    for (std::string line; std::getline(lines, line);)
      {
        const std::string t = trimmed(line);
        if (t.rfind("subsection ", 0) == 0)
          sections.push_back(trimmed(t.substr(11)));
        else if (t == "end" && !sections.empty())
          sections.pop_back();
        else if (t.rfind("#", 0) == 0)
          stated = stated || t.find("Allowed:") != std::string::npos;
        else if (t.rfind("set ", 0) == 0 && !stated)
          {
            // The JSON tree names entries as printed or mangled.
            const auto                   eq   = t.find('=');
            const auto                   name = trimmed(t.substr(4, eq - 4));
            boost::optional<std::string> node;
            for (const bool mangle : {false, true})
              {
                std::string path;
                for (const std::string &section : sections)
                  path += (mangle ? mangled(section) : section) + '\x1f';
                path += (mangle ? mangled(name) : name)
                        + "\x1fpattern_description";
                if (!node)
                  node = tree.get_optional<std::string>(
                    boost::property_tree::ptree::path_type(path, '\x1f'));
              }
            const std::string range = node ? allowed(*node) : std::string();
            if (!range.empty())
              out << line.substr(0, line.find('s')) << "# Allowed: " << range
                  << ".\n";
          }
        if (t.rfind("#", 0) != 0)
          stated = false;
        out << line << '\n';
      }
  }

  void
  reject_entry(const std::string &name,
               const std::string &value,
               const std::string &message)
  {
    throw InputError("entry '" + name + "' = " + value + ": " + message);
  }
} // namespace compax::cli

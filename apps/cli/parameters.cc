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
    check_representable_numbers(prm);
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

    /// One line of a .prm as ParameterHandler prints it: the subsections
    /// it lies in and, for a "set" line, the entry's name and value.
    struct PrmLine
    {
      std::string              raw, text;
      std::vector<std::string> sections;
      bool                     entry = false;
      std::string              name, value;
    };

    /// Calls visit(PrmLine) for every line of @p prm_text.
    template <typename Visit>
    void
    for_each_prm_line(const std::string &prm_text, Visit &&visit)
    {
      std::istringstream lines(prm_text);
      PrmLine            l;
      for (std::string raw; std::getline(lines, raw);)
        {
          l.raw   = raw;
          l.text  = trimmed(raw);
          l.entry = false;
          if (l.text.rfind("subsection ", 0) == 0)
            l.sections.push_back(trimmed(l.text.substr(11)));
          else if (l.text == "end" && !l.sections.empty())
            l.sections.pop_back();
          else if (l.text.rfind("set ", 0) == 0)
            {
              const auto eq = l.text.find('=');
              l.entry       = true;
              l.name        = trimmed(l.text.substr(4, eq - 4));
              l.value
                = eq == std::string::npos ? "" : trimmed(l.text.substr(eq + 1));
            }
          visit(l);
        }
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
    std::string text;
    const auto  matches
      = [](const std::string &path, const std::vector<std::string> &list) {
          for (const std::string &p : list)
            if (lies_below(path, p))
              return true;
          return false;
        };
    for_each_prm_line(all.str(), [&](const PrmLine &l) {
      if (!l.entry)
        return;
      std::string path;
      for (const std::string &s : l.sections)
        path += s + "/";
      path += l.name;
      if ((!include.empty() && !matches(path, include))
          || matches(path, exclude))
        return;
      std::string canonical;
      if (matches(path, files))
        {
          const std::string hash
            = l.value.empty()
                ? std::string()
                : coupling::file_hash(resolve_input_path(l.value).string());
          canonical = l.value.empty() ? ""
                      : hash.empty()  ? "missing"
                                      : "content " + hash;
        }
      else
        {
          std::istringstream items(l.value);
          bool               first = true;
          for (std::string item; std::getline(items, item, ',');)
            {
              canonical += (first ? "" : ", ") + canonical_item(item);
              first = false;
            }
        }
      text += path + " = " + canonical + "\n";
    });
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

    /// The parameters as ParameterHandler's JSON tree (documentation and
    /// pattern of every entry); empty if it cannot be read.
    boost::property_tree::ptree
    pattern_tree(const dealii::ParameterHandler &prm)
    {
      std::ostringstream json;
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
          tree.clear();
        }
      return tree;
    }

    /// The machine description of the pattern of the entry on line @p l,
    /// from ParameterHandler's JSON tree; empty if it is not found.
    std::string
    pattern_description(const boost::property_tree::ptree &tree,
                        const PrmLine                     &l)
    {
      // The JSON tree names entries as printed or mangled.
      for (const bool mangle : {false, true})
        {
          std::string path;
          for (const std::string &section : l.sections)
            path += (mangle ? mangled(section) : section) + '\x1f';
          path
            += (mangle ? mangled(l.name) : l.name) + "\x1fpattern_description";
          if (const auto node = tree.get_optional<std::string>(
                boost::property_tree::ptree::path_type(path, '\x1f')))
            return *node;
        }
      return {};
    }
  } // namespace

  void
  check_representable_numbers(const dealii::ParameterHandler &prm)
  {
    std::ostringstream text;
    prm.print_parameters(text,
                         dealii::ParameterHandler::ShortPRM
                           | dealii::ParameterHandler::KeepDeclarationOrder);
    const boost::property_tree::ptree tree = pattern_tree(prm);
    for_each_prm_line(text.str(), [&](const PrmLine &l) {
      if (!l.entry)
        return;
      const std::string pattern = pattern_description(tree, l);
      // Real numbers and lists of them (deal.II's patterns accept what
      // get_double() then refuses).
      if (pattern.find("[Double") == std::string::npos
          && pattern.find("[Real number") == std::string::npos)
        return;
      std::istringstream items(l.value);
      for (std::string item; std::getline(items, item, ',');)
        {
          const std::string t = trimmed(item);
          errno               = 0;
          char *end           = nullptr;
          std::strtod(t.c_str(), &end);
          if (!t.empty() && end != t.c_str() && errno == ERANGE)
            {
              std::string path;
              for (const std::string &section : l.sections)
                path += section + "/";
              reject_entry(path + l.name,
                           l.value,
                           "'" + t
                             + "' is not representable as a double "
                               "(magnitudes between 2.2e-308 and 1.8e308, "
                               "or 0)");
            }
        }
    });
  }

  void
  print_documented_parameters(const dealii::ParameterHandler &prm,
                              std::ostream                   &out)
  {
    std::ostringstream text;
    prm.print_parameters(text,
                         dealii::ParameterHandler::PRM
                           | dealii::ParameterHandler::KeepDeclarationOrder);
    const boost::property_tree::ptree tree = pattern_tree(prm);
    bool stated = false; // the comment names the allowed values
    for_each_prm_line(text.str(), [&](const PrmLine &l) {
      const bool comment = l.text.rfind("#", 0) == 0;
      if (comment)
        stated = stated || l.text.find("Allowed:") != std::string::npos;
      else if (l.entry && !stated)
        {
          const std::string range = allowed(pattern_description(tree, l));
          if (!range.empty())
            out << l.raw.substr(0, l.raw.find('s')) << "# Allowed: " << range
                << ".\n";
        }
      if (!comment)
        stated = false;
      out << l.raw << '\n';
    });
  }

  namespace
  {
    /// Inverse of mangled(): "_xx" (two hex digits) is the byte xx.
    std::string
    demangled(const std::string &name)
    {
      std::string result;
      for (std::size_t k = 0; k < name.size(); ++k)
        if (name[k] == '_' && k + 2 < name.size()
            && std::isxdigit(static_cast<unsigned char>(name[k + 1]))
            && std::isxdigit(static_cast<unsigned char>(name[k + 2])))
          {
            result += static_cast<char>(
              std::stoi(name.substr(k + 1, 2), nullptr, 16));
            k += 2;
          }
        else
          result += name[k];
      return result;
    }

    /// A table cell: no line breaks, '|' escaped.
    std::string
    cell(const std::string &text)
    {
      std::string result;
      for (const char c : text)
        if (c == '\n')
          result += ' ';
        else if (c == '|')
          result += "\\|";
        else
          result += c;
      return result.empty() ? " " : result;
    }

    /// One subsection of the JSON tree: its entries as a table, then its
    /// subsections under deeper headings.
    void
    write_section_markdown(const boost::property_tree::ptree &section,
                           const std::string                 &path,
                           int                                level,
                           std::ostream                      &out)
    {
      bool table = false;
      for (const auto &[key, node] : section)
        if (node.get_optional<std::string>("pattern_description"))
          {
            if (!table)
              out << "| entry | default | allowed | meaning |\n"
                  << "| --- | --- | --- | --- |\n";
            table = true;
            const std::string range
              = allowed(node.get<std::string>("pattern_description"));
            out << "| `" << cell(demangled(key)) << "` | `"
                << cell(node.get<std::string>("default_value", "")) << "` | "
                << cell(range) << " | "
                << cell(node.get<std::string>("documentation", "")) << " |\n";
          }
      if (table)
        out << '\n';
      for (const auto &[key, node] : section)
        if (!node.get_optional<std::string>("pattern_description")
            && !node.empty())
          {
            const std::string name
              = path.empty() ? demangled(key) : path + "/" + demangled(key);
            out << std::string(level, '#') << " " << name << "\n\n";
            write_section_markdown(node, name, level + 1, out);
          }
    }
  } // namespace

  void
  write_parameters_markdown(const dealii::ParameterHandler &prm,
                            const int                       level,
                            std::ostream                   &out)
  {
    write_section_markdown(pattern_tree(prm), "", level, out);
  }

  void
  reject_entry(const std::string &name,
               const std::string &value,
               const std::string &message)
  {
    throw InputError("entry '" + name + "' = " + value + ": " + message);
  }
} // namespace compax::cli

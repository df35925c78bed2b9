#include "input/parameter_documentation.h"

#include "input/prm_lines.h"

#include <sstream>
#include <string>

namespace compax::input
{
  using prm_lines::demangled;
  using prm_lines::pattern_description;
  using prm_lines::pattern_tree;
  using prm_lines::PrmLine;

  namespace
  {
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
      if (d.rfind("[MultipleSelection ", 0) == 0)
        {
          std::string options = d.substr(19, d.size() - 20);
          while (!options.empty() && options.back() == ' ')
            options.pop_back();
          return "a comma-separated list of any of " + options;
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
  print_documented_parameters(const dealii::ParameterHandler &prm,
                              std::ostream                   &out)
  {
    std::ostringstream text;
    prm.print_parameters(text,
                         dealii::ParameterHandler::PRM
                           | dealii::ParameterHandler::KeepDeclarationOrder);
    const boost::property_tree::ptree tree = pattern_tree(prm);
    bool stated = false; // the comment names the allowed values
    prm_lines::for_each_prm_line(text.str(), [&](const PrmLine &l) {
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

  void
  write_parameters_markdown(const dealii::ParameterHandler &prm,
                            const int                       level,
                            std::ostream                   &out)
  {
    write_section_markdown(pattern_tree(prm), "", level, out);
  }
} // namespace compax::input

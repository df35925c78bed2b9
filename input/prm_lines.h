#pragma once

#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/ptree.hpp>

#include <sstream>
#include <string>
#include <vector>

/**
 * @file
 * Reading back what ParameterHandler prints: the fingerprints, the range
 * checks and the documentation all walk its PRM text line by line and look
 * up each entry's pattern in its JSON tree.
 */

namespace compax::input::prm_lines
{
  /// @p text without leading and trailing blanks and tabs.
  std::string
  trimmed(const std::string &text);

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

  /// The parameters as ParameterHandler's JSON tree (documentation and
  /// pattern of every entry); empty if it cannot be read.
  boost::property_tree::ptree
  pattern_tree(const dealii::ParameterHandler &prm);

  /// The machine description of the pattern of the entry on line @p l,
  /// from ParameterHandler's JSON tree; empty if it is not found.
  std::string
  pattern_description(const boost::property_tree::ptree &tree,
                      const PrmLine                     &l);

  /// Inverse of ParameterHandler's mangling of names in its JSON tree:
  /// "_xx" (two hex digits) is the byte xx.
  std::string
  demangled(const std::string &name);
} // namespace compax::input::prm_lines

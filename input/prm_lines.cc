#include "input/prm_lines.h"

#include <boost/property_tree/json_parser.hpp>

#include <cctype>
#include <string>

namespace compax::input::prm_lines
{
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
  } // namespace

  std::string
  trimmed(const std::string &text)
  {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
      return {};
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
  }

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

  std::string
  pattern_description(const boost::property_tree::ptree &tree, const PrmLine &l)
  {
    // The JSON tree names entries as printed or mangled.
    for (const bool mangle : {false, true})
      {
        std::string path;
        for (const std::string &section : l.sections)
          path += (mangle ? mangled(section) : section) + '\x1f';
        path += (mangle ? mangled(l.name) : l.name) + "\x1fpattern_description";
        if (const auto node = tree.get_optional<std::string>(
              boost::property_tree::ptree::path_type(path, '\x1f')))
          return *node;
      }
    return {};
  }

  std::string
  demangled(const std::string &name)
  {
    std::string result;
    for (std::size_t k = 0; k < name.size(); ++k)
      if (name[k] == '_' && k + 2 < name.size()
          && std::isxdigit(static_cast<unsigned char>(name[k + 1]))
          && std::isxdigit(static_cast<unsigned char>(name[k + 2])))
        {
          result
            += static_cast<char>(std::stoi(name.substr(k + 1, 2), nullptr, 16));
          k += 2;
        }
      else
        result += name[k];
    return result;
  }
} // namespace compax::input::prm_lines

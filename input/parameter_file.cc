#include "input/parameter_file.h"

#include "input/input_error.h"
#include "input/prm_lines.h"

#include <deal.II/base/exceptions.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace compax::input
{
  namespace
  {
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

    std::filesystem::path last_parameter_file_directory;
  } // namespace

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

  void
  check_representable_numbers(const dealii::ParameterHandler &prm)
  {
    std::ostringstream text;
    prm.print_parameters(text,
                         dealii::ParameterHandler::ShortPRM
                           | dealii::ParameterHandler::KeepDeclarationOrder);
    const boost::property_tree::ptree tree = prm_lines::pattern_tree(prm);
    prm_lines::for_each_prm_line(text.str(), [&](const prm_lines::PrmLine &l) {
      if (!l.entry)
        return;
      const std::string pattern = prm_lines::pattern_description(tree, l);
      // Real numbers and lists of them (deal.II's patterns accept what
      // get_double() then refuses).
      if (pattern.find("[Double") == std::string::npos
          && pattern.find("[Real number") == std::string::npos)
        return;
      std::istringstream items(l.value);
      for (std::string item; std::getline(items, item, ',');)
        {
          const std::string t = prm_lines::trimmed(item);
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
} // namespace compax::input

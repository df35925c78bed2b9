#include "input/canonical_parameters.h"

#include "input/parameter_file.h"
#include "input/prm_lines.h"
#include "io/content_hash.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace compax::input
{
  using prm_lines::PrmLine;
  using prm_lines::trimmed;

  namespace
  {
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
    std::string text;
    const auto  matches
      = [](const std::string &path, const std::vector<std::string> &list) {
          for (const std::string &p : list)
            if (lies_below(path, p))
              return true;
          return false;
        };
    prm_lines::for_each_prm_line(all.str(), [&](const PrmLine &l) {
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
                : io::file_hash(resolve_input_path(l.value).string());
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
} // namespace compax::input

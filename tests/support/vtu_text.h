#pragma once

// A written VTK XML file read back for the tests of the particle snapshots.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace compax::testing
{
  /// The text of a .vtu file and the values of its named data arrays.
  struct VtuText
  {
    explicit VtuText(const std::filesystem::path &file)
    {
      std::ifstream     in(file);
      std::stringstream buffer;
      buffer << in.rdbuf();
      text = buffer.str();
    }

    /// Whether a DataArray called @p name is written.
    bool
    has_array(const std::string &name) const
    {
      return text.find("Name=\"" + name + "\"") != std::string::npos;
    }

    /// The first @p n values of the DataArray called @p name; empty if it
    /// is not written.
    std::vector<double>
    array(const std::string &name, const std::size_t n) const
    {
      const auto at = text.find("Name=\"" + name + "\"");
      if (at == std::string::npos)
        return {};
      std::istringstream  values(text.substr(text.find('>', at) + 1));
      std::vector<double> v(n);
      for (double &x : v)
        values >> x;
      return v;
    }

    std::string text;
  };
} // namespace compax::testing

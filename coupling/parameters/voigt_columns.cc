#include "coupling/parameters/voigt_columns.h"

namespace compax::coupling
{
  std::vector<std::string>
  voigt_columns(const std::string &tensor)
  {
    std::vector<std::string> columns;
    for (const char *component : {"xx", "yy", "zz", "yz", "xz", "xy"})
      columns.push_back(tensor + "_" + component);
    return columns;
  }
} // namespace compax::coupling

#include "input/input_error.h"

namespace compax::input
{
  void
  reject_entry(const std::string &name,
               const std::string &value,
               const std::string &message)
  {
    throw InputError("entry '" + name + "' = " + value + ": " + message);
  }
} // namespace compax::input

#pragma once

#include <stdexcept>
#include <string>

namespace compax::input
{
  /**
   * Bad input from the user: an unknown or malformed parameter, a value out
   * of range, a missing file. `compax` prints what() alone and exits with
   * code 2, leaving no output folder behind; a library caller gets the same
   * message naming the entry, its value and the allowed range.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Throws an InputError "entry 'name' = value: message" for checks that
  /// involve several entries.
  [[noreturn]] void
  reject_entry(const std::string &name,
               const std::string &value,
               const std::string &message);
} // namespace compax::input

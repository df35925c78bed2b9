#pragma once

#include <stdexcept>
#include <string>

namespace compax::io
{
  /**
   * A file that cannot be read or written as asked: what() names the file,
   * as "<what_file> '<file>': <reason>"; reason() is the problem alone,
   * one line, for messages that name the file themselves (an input entry
   * and its value). The base of the CSV and archive errors.
   */
  class FileError : public std::runtime_error
  {
  public:
    /// @p what_file says what the file is, e.g. "CSV file".
    FileError(const std::string &what_file,
              const std::string &file,
              const std::string &reason);

    const std::string &
    reason() const
    {
      return why;
    }

  private:
    std::string why;
  };
} // namespace compax::io

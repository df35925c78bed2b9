#include "io/file_error.h"

namespace compax::io
{
  FileError::FileError(const std::string &what_file,
                       const std::string &file,
                       const std::string &reason)
      : std::runtime_error(what_file + " '" + file + "': " + reason)
      , why(reason)
  {
  }
} // namespace compax::io

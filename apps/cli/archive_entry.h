#pragma once

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "coupling/hdf5_archive.h"

#include <string>

namespace compax::cli
{
  /**
   * Reads the archive that the entry @p entry names (@p file) with
   * @p read() and turns whatever goes wrong into bad input naming the entry
   * and its value: an archive that is not an intact one of the kind and
   * parameters asked for (coupling::Hdf5ArchiveError) gives its reason,
   * content that does not fit together (any other exception) "a damaged
   * <kind> (...)". An InputError of @p read passes unchanged.
   */
  template <typename Read>
  auto
  read_archive_entry(const std::string &entry,
                     const std::string &file,
                     const std::string &kind,
                     Read             &&read) -> decltype(read())
  {
    try
      {
        return read();
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const coupling::Hdf5ArchiveError &e)
      {
        reject_entry(entry, file, e.reason());
      }
    catch (const std::exception &e)
      {
        reject_entry(entry,
                     file,
                     "a damaged " + coupling::describe_archive_kind(kind) + " ("
                       + e.what() + ")");
      }
  }
} // namespace compax::cli

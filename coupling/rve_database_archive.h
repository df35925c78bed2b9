#pragma once

#include "coupling/hdf5_archive.h"
#include "coupling/rve_database.h"
#include "dem/solver/contact_model.h"

#include <filesystem>
#include <string>

namespace compax::coupling
{
  /// Writes the rows and branches of a database into an open archive
  /// (what database.h5 and the database checkpoints hold).
  void
  write_database(Hdf5ArchiveWriter &archive, const RveDatabase &database);

  /// Reads what write_database() wrote, exactly; throws on a malformed
  /// archive.
  RveDatabase
  read_database(const Hdf5ArchiveReader &archive);

  /// @p file (database.h5): an archive of kind "rve-database" with the
  /// canonical text of the @p parameters the database was computed with,
  /// holding its rows (with deformation gradient and parent row) and its
  /// branch summaries.
  void
  write_database_archive(const std::filesystem::path &file,
                         const RveDatabase           &database,
                         const std::string           &parameters);

  /// A database checkpoint (@p file, its folder created): the rows and
  /// branches so far and the compaction cell @p bed, which a run resumed
  /// from it continues (DatabaseResume); @p parameters must match on
  /// resume.
  void
  write_database_checkpoint(const std::filesystem::path &file,
                            const std::string           &parameters,
                            const RveDatabase           &database,
                            const dem::PeriodicBed      &bed);

  /// Reads what write_database_checkpoint() wrote. Throws Hdf5ArchiveError
  /// for a foreign or damaged archive or other @p parameters, and
  /// std::runtime_error for content that does not fit together.
  DatabaseResume
  read_database_checkpoint(const std::string       &file,
                           const std::string       &parameters,
                           const dem::ContactModel &model);
} // namespace compax::coupling

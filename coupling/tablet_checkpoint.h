#pragma once

#include "fem/tablet_process.h"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace compax::coupling
{
  /**
   * What a `compax tablet` checkpoint holds besides the solver state of
   * every rank (solver.<rank>.bin, and rve.<rank>.h5 of an FE2 material):
   * the steps so far and the field output lists. It is the archive
   * checkpoint/tablet.h5 (kind "tablet", with the parameters that must
   * match on resume), which also lists every other file of the checkpoint
   * folder with the hash of its content, so that nothing is read from them
   * before they are known to be the files this checkpoint was written with.
   */
  struct TabletCheckpoint
  {
    std::vector<fem::TabletStep> steps;
    /// tablet.pvd entries so far, "time name" per line.
    std::string fields;
    /// The XDMF entries so far (boost text archive).
    std::string xdmf;
  };

  /// Writes @p folder/tablet.h5 after the ranks wrote their state into
  /// @p folder (one process, rank 0).
  void
  write_tablet_checkpoint(const std::filesystem::path &folder,
                          const std::string           &parameters,
                          unsigned int                 ranks,
                          const TabletCheckpoint      &checkpoint);

  /**
   * Reads @p folder/tablet.h5 and checks every file it lists; throws
   * Hdf5ArchiveError or std::runtime_error with a one-line
   * reason. @p ranks, if given, must be the number of MPI ranks it was
   * written with.
   */
  TabletCheckpoint
  read_tablet_checkpoint(const std::filesystem::path &folder,
                         const std::string           &parameters,
                         std::optional<unsigned int>  ranks);

  /// Why a run folder's checkpoint cannot be resumed, as one line (a
  /// program names its input with it; `compax tablet` gives it as bad
  /// input of Output/Resume from).
  class TabletResumeError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * The checkpoint of the run folder @p run_folder (its checkpoint/
   * folder), read and checked as read_tablet_checkpoint() does; throws
   * TabletResumeError with the reason whatever is wrong.
   */
  TabletCheckpoint
  read_tablet_resume(const std::filesystem::path &run_folder,
                     const std::string           &parameters,
                     std::optional<unsigned int>  ranks);
} // namespace compax::coupling

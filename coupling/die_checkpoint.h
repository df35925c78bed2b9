#pragma once

#include "dem/die/die_compaction.h"
#include "dem/solver/contact_model.h"

#include <string>
#include <utility>
#include <vector>

namespace compax::coupling
{
  /**
   * The per-branch output of a die run so far, as a compaction checkpoint
   * holds it: the rows of fabric.csv and force_histograms.csv (text, one
   * row a line) and every snapshot and branch checkpoint with the hash of
   * its content. A resumed run writes the rows and takes the files over
   * from the checkpoint's run folder, so that its output is complete. A
   * study run without such output checkpoints an empty one.
   */
  struct DieBranchFiles
  {
    std::string fabric_rows;
    std::string histogram_rows;
    /// (path relative to the output folder, file_hash) in the order they
    /// were written.
    std::vector<std::pair<std::string, std::string>> files;
  };

  /// What a compaction checkpoint holds: everything dem::DieStudyStart::
  /// resume() needs, and the branch output of the interrupted run.
  struct DieCheckpoint
  {
    dem::Bed         bed;
    dem::DieProgress progress;
    DieBranchFiles   branch_files;
  };

  /**
   * The checkpoint of an interrupted die study (checkpoints/compaction.h5
   * of `compax die`, an archive of kind "die-compaction" with the
   * @p parameters that must match on resume): the bed on the compaction
   * path (save_bed, group "bed"), the DieProgress — compaction targets,
   * how many are done, the die.csv rows (timing aside) and branch
   * summaries so far, jamming density and solver totals — and the
   * per-branch output so far. Written to "<file>.tmp" and renamed, so a
   * kill while writing leaves the previous checkpoint intact. Called from
   * dem::DieStudyObserver::checkpoint, it makes a dem::DieStudy resumable.
   */
  void
  write_die_checkpoint(const std::string      &file,
                       const std::string      &parameters,
                       const dem::Bed         &bed,
                       const dem::DieProgress &progress,
                       const DieBranchFiles   &branch_files = {});

  /**
   * Reads a checkpoint written by write_die_checkpoint() with these
   * @p parameters; throws Hdf5ArchiveError (foreign, damaged or another
   * study's file) or std::runtime_error (inconsistent content) with a
   * one-line reason. Resume with dem::DieStudyStart::resume(bed, progress).
   */
  DieCheckpoint
  read_die_checkpoint(const std::string       &file,
                      const std::string       &parameters,
                      const dem::ContactModel &model);
} // namespace compax::coupling

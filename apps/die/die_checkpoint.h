#pragma once

#include "apps/die/branch_states.h"
#include "dem/die/die_compaction.h"

#include <string>

namespace compax::cli
{
  /**
   * The checkpoint of an interrupted die study (checkpoints/compaction.h5,
   * a coupling archive of kind "die-compaction" with the parameters that
   * must match on resume): the bed on the compaction path (save_bed, group
   * "bed"), the DieProgress — compaction targets, how many are done, the
   * die.csv rows (timing aside) and branch summaries so far, jamming
   * density and solver totals — and the per-branch output so far
   * (BranchFiles: fabric and histogram rows, and the names and hashes of
   * the snapshots and branch checkpoints). Written to "<file>.tmp" and
   * renamed, so a kill while writing leaves the previous checkpoint
   * intact.
   */
  void
  write_die_checkpoint(const std::string      &file,
                       const std::string      &parameters,
                       const dem::Bed         &bed,
                       const dem::DieProgress &progress,
                       const BranchFiles      &branch_files);

  /**
   * Reads a checkpoint written by write_die_checkpoint() with these
   * @p parameters; throws coupling::Hdf5ArchiveError (foreign, damaged or
   * another study's file) or std::runtime_error (inconsistent content)
   * with a one-line reason.
   */
  dem::DieProgress
  read_die_checkpoint(const std::string       &file,
                      const std::string       &parameters,
                      const dem::ContactModel &model,
                      dem::Bed                &bed,
                      BranchFiles             &branch_files);
} // namespace compax::cli

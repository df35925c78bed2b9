#pragma once

#include "dem/die/die_compaction.h"

#include <string>

namespace compax::cli
{
  /**
   * The checkpoint of an interrupted die study (checkpoints/compaction.h5):
   * the bed on the compaction path (save_bed, group "bed") and the
   * DieProgress — compaction targets, how many are done, the die.csv rows
   * and branch summaries so far, jamming density and solver totals. Written
   * to "<file>.tmp" and renamed, so a kill while writing leaves the
   * previous checkpoint intact.
   */
  void
  write_die_checkpoint(const std::string      &file,
                       const dem::Bed         &bed,
                       const dem::DieProgress &progress);

  /// Reads a checkpoint written by write_die_checkpoint(); throws
  /// std::runtime_error (or coupling::Hdf5ArchiveError) naming what is wrong.
  dem::DieProgress
  read_die_checkpoint(const std::string       &file,
                      const dem::ContactModel &model,
                      dem::Bed                &bed);
} // namespace compax::cli

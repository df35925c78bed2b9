#pragma once

#include "dem/dynamics/uniaxial_compaction.h"

#include <string>

namespace compax::cli
{
  /// Prints one progress line of a compaction run: phase, done, strain,
  /// stress, steps and an estimate of the time left in the phase.
  void
  print_progress(const std::string             &label,
                 const dem::CompactionProgress &progress);

  /// Prints the totals of a run (particles, density, peak, timing).
  void
  print_summary(const std::string &label, const dem::CompactionSummary &s);
} // namespace compax::cli

#pragma once

#include "dem/die/die_study.h"

#include <filesystem>

namespace compax::cli
{
  /**
   * The tables and plots `compax die` writes from a finished (or failed)
   * study, next to die.csv:
   * - timing.csv: the wall time of every die.csv row (empty for rows taken
   *   over from a checkpoint);
   * - branches.csv: one row per unloading branch (Gonzalez 2018 Secs.
   *   5.3-5.7), with the tablet's E and nu where determined;
   * - fits.csv (parameter,value; SI units; empty where not determined) and
   *   fits.md (the same with the equations and the points behind each fit)
   *   of Eqs. (14)-(24);
   * - die.png: punch and die-wall pressure and Z against in-die density
   *   with the fits of Eqs. (14)-(15); branches.png (if there are
   *   branches): recovery, residual radial pressure, bonding surface and
   *   tablet E with Eqs. (17), (19), (23), (24).
   */
  void
  write_die_outputs(const std::filesystem::path &folder,
                    const dem::DieStudyResult   &result);
} // namespace compax::cli

#pragma once

#include "apps/rve/rve_checkpoint.h"
#include "coupling/parameters/rve_parameters.h"
#include "dem/rve/periodic_bed.h"
#include "dem/rve/rve_path_study.h"

#include <chrono>
#include <filesystem>
#include <vector>

namespace compax::cli
{
  struct RveOutcome
  {
    /// An ExitCode: success, or not_converged (last good state kept).
    int  code    = 0;
    bool stopped = false;
    /// Timings of the path; total: of the run with its output [s].
    dem::RvePathTimings timings;
  };

  /**
   * The files of one path in `folder`: rve.csv, moduli.csv, timing.csv,
   * stress_strain.png, moduli.png, snapshots/ with snapshots.pvd,
   * checkpoints/rve.h5, and last_converged.h5 if a step failed; progress
   * on screen. observer() writes snapshots and checkpoints as the path
   * goes, finish() the rest.
   */
  class RvePathOutput
  {
  public:
    /// `resumed`, if given, is the progress read from a checkpoint: its
    /// rows come first, its snapshots are taken over.
    RvePathOutput(const coupling::RveStudy &study,
                  std::filesystem::path     folder,
                  const RveProgress        *resumed = nullptr);

    dem::RvePathObserver
    observer();

    RveOutcome
    finish(const dem::RvePathResult &result, const dem::RvePathStudy &path);

  private:
    /// The earlier rows and this run's, as a checkpoint stores them.
    RveProgress
    progress(const dem::RvePathResult &result,
             const dem::RvePathState  &state) const;

    void
    snapshot(int step, const dem::PeriodicBed &bed);

    void
    write_snapshot_list() const;

    void
    report(const dem::RvePathStepEvent &e) const;

    const coupling::RveStudy             &study;
    std::filesystem::path                 folder;
    RveProgress                           earlier;
    std::vector<int>                      snapshots;
    std::chrono::steady_clock::time_point started;
  };

  /**
   * Drives a cell along the study's strain path (dem::RvePathStudy),
   * writing the files of RvePathOutput into `folder`. `resumed`, if
   * given, is the progress read from a checkpoint together with `bed`.
   */
  RveOutcome
  run_rve_path(const coupling::RveStudy    &study,
               dem::PeriodicBed             bed,
               const std::filesystem::path &folder,
               const RveProgress           *resumed = nullptr);
} // namespace compax::cli

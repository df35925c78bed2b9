#pragma once

#include "apps/rve/rve_parameters.h"
#include "dem/rve/periodic_bed.h"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace compax::cli
{
  /// Columns of rve.csv and moduli.csv (one row = one vector of numbers in
  /// this order; the stage is 0 loading / 1 unloading, NaN an empty cell).
  const std::vector<std::string> &
  rve_columns();
  const std::vector<std::string> &
  moduli_columns();

  /// Columns of timing.csv: per row of rve.csv computed by this run, the
  /// seconds of its step and of its tangents (kept out of rve.csv and
  /// moduli.csv, so that two runs of one study give the same files).
  const std::vector<std::string> &
  timing_columns();

  /// Index of a column in rve_columns() / moduli_columns().
  std::size_t
  rve_column(const std::string &name);
  std::size_t
  moduli_column(const std::string &name);

  /// Where a path stands: the rows written so far and what the rest of
  /// the path needs (stored in checkpoints).
  struct RveProgress
  {
    std::vector<std::vector<double>> rows;
    std::vector<std::vector<double>> moduli;
    /// Steps with a VTU snapshot.
    std::vector<int> snapshots;
    /// Their hashes (coupling::file_hash), as a checkpoint lists them.
    std::vector<std::string> snapshot_hashes;
    /// Rows of timing.csv (not in checkpoints).
    std::vector<std::vector<double>> timing;
    /// F at the end of loading (unloading starts from it).
    Eigen::Matrix3d loaded_deformation = Eigen::Matrix3d::Identity();
  };

  /// Timings of one run [s].
  struct RveTimings
  {
    double steps         = 0.0;
    int    n_steps       = 0;
    double tangents      = 0.0; ///< condensed + affine, current branch
    int    n_tangents    = 0;
    double fd_tangents   = 0.0;
    int    n_fd_tangents = 0;
    double total         = 0.0;
  };

  struct RveOutcome
  {
    /// An ExitCode: success, or not_converged (last good state kept).
    int         code    = 0;
    bool        stopped = false;
    RveProgress progress;
    RveTimings  timings;
  };

  /**
   * Drives a cell along the study's strain path, writing rve.csv,
   * moduli.csv, stress_strain.png, moduli.png, snapshots/ with
   * snapshots.pvd, and checkpoints/rve.h5 into `folder`. `resumed`, if
   * given, is the progress read from a checkpoint together with `bed`.
   */
  RveOutcome
  run_rve_path(const RveStudy              &study,
               dem::PeriodicBed             bed,
               const std::filesystem::path &folder,
               const RveProgress           *resumed = nullptr);

  /// Writes a checkpoint (cell and progress) atomically.
  void
  write_rve_checkpoint(const std::filesystem::path &file,
                       const RveStudy              &study,
                       const dem::PeriodicBed      &bed,
                       const RveProgress           &progress);

  /// Reads a checkpoint and checks that the earlier snapshots are next to
  /// it; throws InputError naming Checkpoints/Resume from if it is not an
  /// intact RVE checkpoint written with the study's resume_parameters.
  RveProgress
  read_rve_checkpoint(const std::string &file,
                      const RveStudy    &study,
                      dem::PeriodicBed  &bed);
} // namespace compax::cli

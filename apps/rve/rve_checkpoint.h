#pragma once

#include "coupling/parameters/rve_parameters.h"
#include "dem/rve/periodic_bed.h"
#include "dem/rve/rve_path_study.h"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace compax::cli
{
  /// Where a path stands as a checkpoint stores it: the rows written so
  /// far (in the layout of rve_columns() / moduli_columns(), the format of
  /// existing checkpoints) and what the rest of the path needs.
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

  /// Writes a checkpoint (cell and progress) atomically.
  void
  write_rve_checkpoint(const std::filesystem::path &file,
                       const coupling::RveStudy    &study,
                       const dem::PeriodicBed      &bed,
                       const RveProgress           &progress);

  /// Reads a checkpoint and checks that the earlier snapshots are next to
  /// it; throws InputError naming Checkpoints/Resume from if it is not an
  /// intact RVE checkpoint written with the study's resume_parameters.
  RveProgress
  read_rve_checkpoint(const std::string        &file,
                      const coupling::RveStudy &study,
                      dem::PeriodicBed         &bed);

  /// The state of the path study that a checkpoint's progress and cell
  /// stand for (the counts of steps, the sticky jamming, the last state).
  dem::RvePathState
  resumed_state(dem::PeriodicBed   bed,
                const RveProgress &progress,
                double             jamming_pressure);
} // namespace compax::cli

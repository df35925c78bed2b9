#pragma once

#include "coupling/parameters/rve_parameters.h"

#include <filesystem>

namespace compax::cli
{
  /**
   * The RVE-size study (dem::RveSizeStudy) of Size study/Cell sizes: one
   * path per cell size in size-<N>/ (the files of RvePathOutput),
   * rve_size_study.csv (per size the stress at the end of loading and the
   * moduli there and at the end), rve_size_spread.csv (their spread
   * between the sizes) and timing.csv. Returns an ExitCode.
   */
  int
  run_rve_size_study(const coupling::RveStudy    &study,
                     const std::filesystem::path &folder);
} // namespace compax::cli

#pragma once

#include "apps/common/csv_writer.h"
#include "dem/solver/bed.h"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace compax::cli
{
  /**
   * What `compax die` writes at the analysed states of each branch
   * (compaction at the unloading point, unloading at C, ejection):
   * - snapshots/<stage>-<branch>.vtu and particles.pvd for ParaView;
   * - fabric.csv: the axisymmetric spectra a20..a80 of contact normals and
   *   b20..b80 of the mean contact force magnitude (Eqs. 21-22);
   * - force_histograms.csv: counts of contact forces, compressive and
   *   tensile together (Fig. 16);
   * - checkpoints/branch-<k>.h5 at the compaction state, from which that
   *   branch can be rerun, in HDF5 (see bed_checkpoint.h).
   */
  class BranchStateWriter
  {
  public:
    explicit BranchStateWriter(const std::filesystem::path &folder);

    void
    operator()(const dem::Bed &bed, const std::string &stage, int branch);

    /**
     * For a resumed run: takes over what an earlier run wrote in
     * `old_folder` for branches 1..branches (snapshots, fabric and
     * histogram rows, branch checkpoints). Missing files are skipped.
     * @return the number of files or rows that could not be found
     */
    int
    carry_over(const std::filesystem::path &old_folder, int branches);

  private:
    void
    add_snapshot(const std::string &stage, int branch);

    std::filesystem::path                       folder;
    CsvWriter                                   fabric;
    CsvWriter                                   histograms;
    std::vector<std::pair<double, std::string>> snapshots;
  };
} // namespace compax::cli

#pragma once

#include "coupling/die_checkpoint.h"
#include "dem/solver/bed.h"
#include "io/csv_writer.h"

#include <filesystem>
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
   * - checkpoints/branch-<k>.h5 at the compaction state (an archive of
   *   kind "die-branch" with the `state_parameters`), from which that
   *   branch can be rerun (see coupling/die_state_archive.h).
   */
  class BranchStateWriter
  {
  public:
    BranchStateWriter(const std::filesystem::path &folder,
                      std::string                  state_parameters);

    void
    operator()(const dem::Bed &bed, const std::string &stage, int branch);

    /// Everything written so far (flushed to the files first), for a
    /// checkpoint.
    coupling::DieBranchFiles
    so_far();

    /// Throws std::runtime_error naming the first file of @p earlier that is
    /// missing in @p old_folder or differs from the one listed.
    static void
    verify(const std::filesystem::path    &old_folder,
           const coupling::DieBranchFiles &earlier);

    /**
     * For a resumed run: writes the rows of @p earlier and copies its files
     * from `old_folder`, the run folder of the checkpoint. Throws
     * std::runtime_error naming the first file that is missing there or
     * differs from the one the checkpoint lists.
     */
    void
    carry_over(const std::filesystem::path    &old_folder,
               const coupling::DieBranchFiles &earlier);

  private:
    void
    add_snapshot(const std::string &stage, int branch);

    std::filesystem::path                       folder;
    std::string                                 state_parameters;
    io::CsvWriter                               fabric;
    io::CsvWriter                               histograms;
    coupling::DieBranchFiles                    written;
    std::vector<std::pair<double, std::string>> snapshots;
  };
} // namespace compax::cli

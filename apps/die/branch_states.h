#pragma once

#include "apps/common/csv_writer.h"
#include "coupling/hdf5_archive.h"
#include "dem/solver/bed.h"

#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace compax::cli
{
  /**
   * The per-branch output of a die run so far, as a compaction checkpoint
   * holds it: the rows of fabric.csv and force_histograms.csv (text, one
   * row a line) and every snapshot and branch checkpoint with the hash of
   * its content. A resumed run writes the rows and takes the files over
   * from the checkpoint's run folder, so that its output is complete.
   */
  struct BranchFiles
  {
    std::string fabric_rows;
    std::string histogram_rows;
    /// (path relative to the output folder, coupling::file_hash) in the
    /// order they were written.
    std::vector<std::pair<std::string, std::string>> files;
  };

  /// Stores @p files under @p group of an archive.
  void
  save_branch_files(coupling::Hdf5ArchiveWriter &archive,
                    const std::string           &group,
                    const BranchFiles           &files);

  /// Reads what save_branch_files() stored.
  BranchFiles
  load_branch_files(const coupling::Hdf5ArchiveReader &archive,
                    const std::string                 &group);

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
   *   branch can be rerun (see bed_checkpoint.h).
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
    BranchFiles
    so_far();

    /// Throws std::runtime_error naming the first file of @p earlier that is
    /// missing in @p old_folder or differs from the one listed.
    static void
    verify(const std::filesystem::path &old_folder, const BranchFiles &earlier);

    /**
     * For a resumed run: writes the rows of @p earlier and copies its files
     * from `old_folder`, the run folder of the checkpoint. Throws
     * std::runtime_error naming the first file that is missing there or
     * differs from the one the checkpoint lists.
     */
    void
    carry_over(const std::filesystem::path &old_folder,
               const BranchFiles           &earlier);

  private:
    void
    add_snapshot(const std::string &stage, int branch);

    std::filesystem::path                       folder;
    std::string                                 state_parameters;
    CsvWriter                                   fabric;
    CsvWriter                                   histograms;
    BranchFiles                                 written;
    std::vector<std::pair<double, std::string>> snapshots;
  };
} // namespace compax::cli

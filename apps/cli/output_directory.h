#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace compax::cli
{
  /// How a run may use its output folder.
  struct OutputRules
  {
    /// `--overwrite`: an OUTDIR that holds an earlier compax output (and
    /// nothing else) may be replaced.
    bool overwrite = false;
    /// Files the run reads (its .prm): OUTDIR may not hold them.
    std::vector<std::filesystem::path> inputs;
    /// The command and the compax version, recorded in the marker file.
    std::string command;
    std::string version;
  };

  /// The marker file compax writes into every output folder: the command,
  /// the version and the list of files it wrote.
  inline constexpr const char *output_marker = ".compax-output";

  /**
   * Throws InputError if @p path may not be the OUTDIR of a run with
   * @p rules; creates nothing. Always refused: an empty name, `/`, the home
   * folder, the working folder or a folder holding it, a folder holding an
   * input file, an existing file that is not a folder. An existing folder
   * that is not empty is refused unless it holds the output of an earlier
   * compax run (its marker file lists every file in it) and
   * rules.overwrite is set.
   */
  void
  check_output_directory(const std::filesystem::path &path,
                         const OutputRules           &rules);

  /**
   * The output folder of one run, built in a hidden staging folder
   * (.<OUTDIR>.partial-<pid>) next to its final place and moved there only
   * by publish(). While it exists it holds a lock (.<OUTDIR>.lock, flock),
   * so a second run into the same OUTDIR is refused. A run that fails or
   * is rejected leaves no half-written folder: the destructor removes the
   * staging folder (and any parent folders it created) unless it was
   * published. Under MPI, rank 0 does all of it and every rank gets the
   * same staging path and the same errors.
   */
  class OutputDirectory
  {
  public:
    /// Checks @p final_path (check_output_directory), takes the lock and
    /// creates the staging folder; throws InputError if it may not.
    OutputDirectory(std::filesystem::path final_path, OutputRules rules);
    ~OutputDirectory();

    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &
    operator=(const OutputDirectory &)
      = delete;

    /// Where the run writes while it is in progress.
    const std::filesystem::path &
    staging() const
    {
      return staging_path;
    }

    /**
     * Writes the marker file and moves the staging folder to the final
     * path, replacing only an empty folder or (with overwrite) an earlier
     * compax output there. Also for a run that stopped without
     * convergence (its last good state and checkpoints). If OUTDIR was
     * changed by someone else during the run so that it may no longer be
     * replaced, the results stay in the staging folder and InputError says
     * so.
     */
    void
    publish();

    const std::filesystem::path &
    final() const
    {
      return final_path;
    }

  private:
    void
    release_lock();

    std::filesystem::path              final_path;
    std::filesystem::path              staging_path;
    std::filesystem::path              lock_path;
    std::vector<std::filesystem::path> created_parents;
    OutputRules                        rules;
    int                                lock_fd   = -1;
    bool                               published = false;
  };
} // namespace compax::cli

#pragma once

#include <filesystem>

namespace compax::cli
{
  /**
   * The output folder of one run, built in a hidden staging folder next to
   * its final place and moved there only by publish(). A run that fails or
   * is rejected leaves no half-written folder: the destructor removes the
   * staging folder unless it was published (or kept for a restart).
   */
  class OutputDirectory
  {
  public:
    explicit OutputDirectory(std::filesystem::path final_path);
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

    /// Replaces any previous folder at the final path by the staging folder.
    void
    publish();

    /**
     * Publishes what a stopped run wrote (its last good state and
     * checkpoints) under the final path, for a later resume.
     */
    void
    publish_partial();

    const std::filesystem::path &
    final() const
    {
      return final_path;
    }

  private:
    std::filesystem::path final_path;
    std::filesystem::path staging_path;
    bool                  published = false;
  };
} // namespace compax::cli

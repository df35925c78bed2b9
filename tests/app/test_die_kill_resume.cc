// Issue #14, Why 4: a die run killed (SIGKILL, no clean-up) during
// compaction, during an unloading branch and during an ejection, and
// resumed from the checkpoint in its staging folder, writes exactly the
// files of the uninterrupted run: every per-branch file (snapshots, fabric,
// force histograms, branch checkpoints) and the final checkpoint, byte for
// byte; only timing.csv differs (and parameters.prm by its Resume from).
//
// The kill comes from the test hook COMPAX_TEST_KILL_AFTER_ROW of `compax
// die`: the process kills itself right after the named die.csv row reached
// the file, as deterministic as a kill from outside at that moment.

#include "app_test_support.h"

#include <fstream>
#include <sstream>

using compax::testing::AppTest;
using compax::testing::small_die_study;

namespace
{
  /// parameters.prm without its Resume from line.
  std::string
  without_resume(const std::string &text)
  {
    std::istringstream lines(text);
    std::string        kept;
    for (std::string line; std::getline(lines, line);)
      if (line.find("set Resume from") == std::string::npos)
        kept += line + "\n";
    return kept;
  }
} // namespace

class DieKillResume : public AppTest
{
protected:
  /// Every file below `root` by its path relative to it.
  std::map<std::string, std::string>
  files_below(const std::filesystem::path &root) const
  {
    std::map<std::string, std::string> files;
    for (const auto &e : std::filesystem::recursive_directory_iterator(root))
      if (e.is_regular_file())
        files[e.path().lexically_relative(root).string()] = read(e.path());
    return files;
  }
};

TEST_F(DieKillResume, KilledInEveryStageAndResumedWritesTheUninterruptedFiles)
{
  write("study.prm", small_die_study);
  const auto full = compax("die study.prm -o full");
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const auto expected = files_below(folder / "full");
  ASSERT_TRUE(expected.count("checkpoints/compaction.h5"));
  ASSERT_TRUE(expected.count("snapshots/ejection-2.vtu"));
  ASSERT_TRUE(expected.count("timing.csv"));

  // During compaction (target 7, after the checkpoint of target 6), during
  // the unloading of branch 2 and during its ejection.
  for (const std::string row :
       {"compaction,0,7", "unloading,2,5", "ejection,2,1"})
    {
      SCOPED_TRACE(row);
      const auto killed
        = shell("COMPAX_TEST_KILL_AFTER_ROW=" + row + " '" + COMPAX_EXECUTABLE
                + "' die study.prm -o killed");
      ASSERT_NE(killed.exit_code, 0);
      ASSERT_FALSE(std::filesystem::exists(folder / "killed"));
      std::filesystem::path staging;
      for (const auto &e : std::filesystem::directory_iterator(folder))
        if (e.path().filename().string().rfind(".killed.partial-", 0) == 0)
          staging = e.path();
      ASSERT_FALSE(staging.empty());
      // The kill came right after the row.
      const std::string rows = read(staging / "die.csv");
      EXPECT_NE(rows.find("\n" + row + ","), std::string::npos);
      EXPECT_EQ(rows.substr(rows.rfind('\n', rows.size() - 2) + 1,
                            row.size() + 1),
                row + ",");

      write("resume.prm",
            small_die_study + "subsection Protocol\n set Resume from = "
              + (staging / "checkpoints" / "compaction.h5").string()
              + "\nend\n");
      const std::string out     = "resumed-" + row.substr(0, row.find(','));
      const auto        resumed = compax("die resume.prm -o " + out);
      ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
      EXPECT_NE(resumed.out.find("resuming after"), std::string::npos);

      const auto               got = files_below(folder / out);
      std::vector<std::string> expected_names, got_names;
      for (const auto &[name, text] : expected)
        expected_names.push_back(name);
      for (const auto &[name, text] : got)
        got_names.push_back(name);
      EXPECT_EQ(got_names, expected_names);
      for (const auto &[name, text] : expected)
        {
          if (name == "timing.csv" || got.count(name) == 0)
            continue;
          if (name == "parameters.prm")
            {
              EXPECT_EQ(without_resume(got.at(name)), without_resume(text));
            }
          else
            {
              EXPECT_TRUE(got.at(name) == text) << name << " differs";
            }
        }
      // The resumed run times only what it computed: the rows taken over
      // from the checkpoint have no time.
      EXPECT_EQ(got.at("timing.csv")
                  .rfind("stage,branch,step,wall_seconds\n"
                         "compaction,0,0,\n",
                         0),
                0u);
      std::filesystem::remove_all(staging);
      std::filesystem::remove(folder / ".killed.lock");
    }
}

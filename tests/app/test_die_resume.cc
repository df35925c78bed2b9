// Restart of an interrupted die study: a run stopped after some compaction
// steps (with its checkpoint) and resumed from checkpoints/compaction.h5
// gives the same die.csv and branches.csv as the uninterrupted run, and a
// checkpoint that does not fit the parameters is rejected.

#include "app_test_support.h"

#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <thread>

using compax::testing::AppTest;
using compax::testing::Csv;

namespace
{
  /// die_study_150 with a checkpoint every 7 targets.
  std::string
  study(const std::string &extra_protocol)
  {
    return compax::testing::die_study_150(" set Checkpoint interval = 7\n"
                                          + extra_protocol);
  }

  /// Whether two tables hold the same numbers to `relative` (columns that
  /// measure time are skipped).
  void
  expect_same_numbers(const Csv &a, const Csv &b, const double relative)
  {
    ASSERT_EQ(a.header, b.header);
    ASSERT_EQ(a.rows(), b.rows());
    for (const auto &name : a.header)
      {
        if (name == "wall_seconds")
          continue;
        const auto &x = a.column.at(name), &y = b.column.at(name);
        for (std::size_t i = 0; i < x.size(); ++i)
          {
            if (std::isnan(x[i]))
              {
                EXPECT_EQ(a.text.at(name)[i], b.text.at(name)[i]);
                continue;
              }
            EXPECT_NEAR(x[i], y[i], relative * std::abs(x[i]) + 1e-300)
              << name << ", row " << i;
          }
      }
  }
} // namespace

class DieResume : public AppTest
{
protected:
  /// full/<file> and resumed/<file> hold the same numbers to 1e-9.
  void
  expect_resumed_equals_full(const std::string &file) const
  {
    expect_same_numbers(Csv(folder / "full" / file),
                        Csv(folder / "resumed" / file),
                        1e-9);
  }
};

TEST_F(DieResume, StoppedAndResumedRunEqualsTheUninterruptedRun)
{
  write("full.prm", study(""));
  const auto full = compax("die full.prm -o full");
  ASSERT_EQ(full.exit_code, 0) << full.err;

  // Interrupted at the second checkpoint, after 14 of the 17 targets, past
  // the first unloading branch.
  write("part.prm", study(" set Stop after compaction steps = 14\n"));
  const auto part = compax("die part.prm -o part");
  ASSERT_EQ(part.exit_code, 0) << part.err;
  ASSERT_TRUE(
    std::filesystem::exists(folder / "part" / "checkpoints" / "compaction.h5"));
  const Csv part_rows(folder / "part" / "die.csv");
  const Csv full_rows(folder / "full" / "die.csv");
  ASSERT_LT(part_rows.rows(), full_rows.rows());
  ASSERT_EQ(Csv(folder / "part" / "branches.csv").rows(), 1u);

  write("resume.prm",
        study(" set Resume from = part/checkpoints/compaction.h5\n"));
  const auto resumed = compax("die resume.prm -o resumed");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("resuming after 14 of 17"), std::string::npos)
    << resumed.out;

  expect_resumed_equals_full("die.csv");
  const Csv branches(folder / "resumed" / "branches.csv");
  EXPECT_EQ(branches.rows(), 2u);
  expect_resumed_equals_full("branches.csv");
  // The first branch's files come over from the interrupted run.
  EXPECT_TRUE(std::filesystem::exists(folder / "resumed" / "checkpoints"
                                      / "branch-1.h5"));
  EXPECT_TRUE(std::filesystem::exists(folder / "resumed" / "snapshots"
                                      / "ejection-1.vtu"));
  expect_resumed_equals_full("fabric.csv");
}

TEST_F(DieResume, KilledRunResumesFromItsStagedCheckpoint)
{
  write("full.prm", study(""));
  ASSERT_EQ(compax("die full.prm -o full").exit_code, 0);

  // The same study in the background, killed (SIGKILL: no clean-up) as soon
  // as its first checkpoint exists in the staging folder.
  const pid_t pid = start("die full.prm -o out", "out.log");
  ASSERT_GT(pid, 0);
  std::filesystem::path checkpoint;
  for (int k = 0; k < 6000 && checkpoint.empty(); ++k)
    {
      for (const auto &e : std::filesystem::directory_iterator(folder))
        if (e.path().filename().string().rfind(".out.partial-", 0) == 0
            && std::filesystem::exists(e.path() / "checkpoints"
                                       / "compaction.h5"))
          checkpoint = e.path() / "checkpoints" / "compaction.h5";
      if (checkpoint.empty())
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  ASSERT_FALSE(checkpoint.empty()) << "no checkpoint appeared";
  ::kill(pid, SIGKILL);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_FALSE(std::filesystem::exists(folder / "out"))
    << "the run finished before it could be killed";

  write("resume.prm",
        study(" set Resume from = " + checkpoint.string() + "\n"));
  const auto resumed = compax("die resume.prm -o resumed");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("resuming after"), std::string::npos);
  expect_resumed_equals_full("die.csv");
  expect_resumed_equals_full("branches.csv");
}

TEST_F(DieResume, CheckpointOfAnotherStudyIsRejected)
{
  write("part.prm", study(" set Stop after compaction steps = 4\n"));
  ASSERT_EQ(compax("die part.prm -o part").exit_code, 0);
  // Other compaction steps: the targets done no longer match.
  write("other.prm",
        "subsection Packing\n set Number of particles = 150\n"
        " set Die diameter = 3e-3\nend\n"
        "subsection Protocol\n set Final relative density = 0.8\n"
        " set Compaction steps = 10\n set Unloading points = 0.8\n"
        " set Resume from = part/checkpoints/compaction.h5\nend\n");
  expect_refused_without_output(compax("die other.prm -o other"),
                                {"Resume from", "compaction target"},
                                "other");

  // Not a checkpoint at all.
  write("not.h5", "plain text");
  write("bad.prm", "subsection Protocol\n set Resume from = not.h5\nend\n");
  expect_refused_without_output(compax("die bad.prm -o bad"),
                                {"Resume from"},
                                "bad");
}

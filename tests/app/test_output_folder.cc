// Issue #14, Why 1: compax never deletes or overwrites what it did not
// write. The working folder, its parents, the home folder, a folder holding
// the .prm, an existing file and a folder holding a user's files are refused
// as OUTDIR (exit 2, one line, every file as it was); an earlier compax
// output is replaced only with --overwrite and only if nothing else is in
// it; a second run into an OUTDIR in use is refused.

#include "app_test_support.h"

#include <signal.h>

#include <chrono>
#include <fstream>
#include <thread>

using compax::testing::AppTest;
using compax::testing::Csv;

class OutputFolder : public AppTest
{
protected:
  /// A working folder with a user's files in it.
  void
  SetUp() override
  {
    AppTest::SetUp();
    write("important.txt", "the user's notes\n");
    std::filesystem::create_directories(folder / "sub");
    write("sub/keep.txt", "keep me\n");
    write("input.prm", "# the defaults\n");
  }
};

TEST_F(OutputFolder, TheWorkingFolderIsRefused)
{
  const auto before = contents();
  expect_refused(compax("contact -o ."),
                 {"output folder (-o) '.' is the working folder"},
                 before);
  expect_refused(compax("contact input.prm -o ."),
                 {"output folder (-o) '.' is the working folder"},
                 before);
  expect_refused(compax("contact -o ./"), {"is the working folder"}, before);
}

TEST_F(OutputFolder, AFolderHoldingTheWorkingFolderIsRefused)
{
  const auto before = contents();
  expect_refused(compax("contact -o .."),
                 {"output folder (-o) '..' holds the working folder"},
                 before);
  expect_refused(compax("contact -o /"),
                 {"output folder (-o) '/' is the root folder"},
                 before);
}

TEST_F(OutputFolder, TheHomeFolderIsRefused)
{
  std::filesystem::create_directories(folder / "home");
  write("home/.profile", "# the user's profile\n");
  const auto before = contents();
  // `-o ~` as a shell expands it.
  expect_refused(shell("export HOME='" + (folder / "home").string() + "' && '"
                       + COMPAX_EXECUTABLE + "' contact -o ~"),
                 {"is the home folder"},
                 before);
}

TEST_F(OutputFolder, AnExistingFileIsRefused)
{
  const auto before = contents();
  expect_refused(compax("contact -o important.txt"),
                 {"output folder (-o) 'important.txt' is an existing file, "
                  "not a folder"},
                 before);
  expect_refused(compax("contact -o important.txt --overwrite"),
                 {"is an existing file"},
                 before);
}

TEST_F(OutputFolder, AFolderWithTheUsersFilesIsRefused)
{
  const auto before = contents();
  expect_refused(compax("contact -o sub"),
                 {"output folder (-o) 'sub' exists and holds files that "
                  "compax did not write"},
                 before);
  expect_refused(compax("contact -o sub --overwrite"),
                 {"holds files that compax did not write"},
                 before);
  // An OUTDIR holding a user's important.txt and sub/keep.txt.
  std::filesystem::create_directories(folder / "mine" / "sub");
  write("mine/important.txt", "the user's notes\n");
  write("mine/sub/keep.txt", "keep me\n");
  const auto with_mine = contents();
  expect_refused(compax("contact -o mine"),
                 {"output folder (-o) 'mine' exists and holds files that "
                  "compax did not write; compax never deletes them"},
                 with_mine);
  expect_refused(compax("contact -o mine --overwrite"),
                 {"holds files that compax did not write"},
                 with_mine);
  // So does a run that would end without convergence (exit 3).
  write("stalls.prm",
        "subsection Packing\n set Number of particles = 60\n"
        " set Die diameter = 2e-3\nend\n"
        "subsection Solver\n set Maximum iterations = 1\nend\n");
  const auto with_prm = contents();
  expect_refused(compax("die stalls.prm -o mine"),
                 {"holds files that compax did not write"},
                 with_prm);
  // The default OUTDIR too.
  std::filesystem::create_directories(folder / "contact-output");
  write("contact-output/mine.txt", "mine\n");
  const auto with_default = contents();
  expect_refused(compax("contact"),
                 {"'contact-output' exists and holds files"},
                 with_default);
}

TEST_F(OutputFolder, AFolderHoldingTheParameterFileIsRefused)
{
  std::filesystem::create_directories(folder / "study");
  write("study/in.prm", "# the defaults\n");
  const auto before = contents();
  expect_refused(compax("contact study/in.prm -o study"),
                 {"output folder (-o) 'study' holds the input file "
                  "'study/in.prm'"},
                 before);
  // Even an earlier compax output with --overwrite.
  ASSERT_EQ(compax("contact -o out").exit_code, 0);
  write("out/in.prm", "# the defaults\n");
  const auto with_output = contents();
  expect_refused(compax("contact out/in.prm -o out --overwrite"),
                 {"holds the input file"},
                 with_output);
}

TEST_F(OutputFolder, AnEarlierOutputIsReplacedOnlyWithOverwrite)
{
  ASSERT_EQ(compax("contact -o out").exit_code, 0);
  // The marker names the command and every file the run wrote.
  const std::string marker = read(folder / "out" / ".compax-output");
  EXPECT_EQ(marker.rfind("compax-output 1\ncommand contact\n", 0), 0u)
    << marker;
  EXPECT_NE(marker.find("\ncontact.csv\n"), std::string::npos) << marker;

  const auto before = contents();
  expect_refused(compax("contact -o out"),
                 {"holds the output of an earlier compax run; add "
                  "--overwrite"},
                 before);
  const auto again = compax("contact -o out --overwrite");
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(folder / "out" / "contact.csv"));
  EXPECT_EQ(read(folder / "important.txt"), "the user's notes\n");

  // A file the user put into it is never deleted.
  write("out/notes.txt", "my notes on this run\n");
  const auto with_notes = contents();
  expect_refused(compax("contact -o out --overwrite"),
                 {"holds an earlier compax output and 'notes.txt', which "
                  "compax did not write"},
                 with_notes);
  // An empty folder is taken.
  std::filesystem::create_directories(folder / "empty");
  EXPECT_EQ(compax("contact -o empty").exit_code, 0);
  EXPECT_TRUE(
    std::filesystem::is_regular_file(folder / "empty" / "contact.csv"));
}

TEST_F(OutputFolder, ASecondRunIntoAnOutdirInUseIsRefused)
{
  write("die.prm",
        "subsection Packing\n set Number of particles = 60\n"
        " set Die diameter = 2e-3\nend\n"
        "subsection Protocol\n set Final relative density = 0.66\n"
        " set Compaction steps = 4\n set Unloading points = 0.66\nend\n");
  const pid_t pid = start("die die.prm -o busy", "busy.log");
  ASSERT_GT(pid, 0);
  // Frozen while it holds the lock (it is taken before the staging folder
  // is made).
  bool staged = false;
  for (int k = 0; k < 20000 && !staged; ++k)
    {
      for (const auto &e : std::filesystem::directory_iterator(folder))
        staged
          = staged
            || e.path().filename().string().rfind(".busy.partial-", 0) == 0;
      if (!staged)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  ::kill(pid, SIGSTOP);
  ASSERT_TRUE(staged);
  ASSERT_TRUE(std::filesystem::exists(folder / ".busy.lock"));
  const auto second = compax("contact -o busy");
  EXPECT_EQ(second.exit_code, 2);
  EXPECT_NE(second.err.find("output folder (-o) 'busy' is in use by another "
                            "compax run (process "
                            + std::to_string(pid) + ")"),
            std::string::npos)
    << second.err;
  EXPECT_EQ(std::count(second.err.begin(), second.err.end(), '\n'), 1);
  ::kill(pid, SIGCONT);
  for (int k = 0; k < 60000 && ::kill(pid, 0) == 0; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  // The first run was not disturbed: it published its die study and
  // released the lock.
  EXPECT_TRUE(std::filesystem::is_regular_file(folder / "busy" / "die.csv"))
    << read(folder / "busy.log");
  EXPECT_FALSE(std::filesystem::exists(folder / "busy" / "contact.csv"));
  EXPECT_FALSE(std::filesystem::exists(folder / ".busy.lock"));
}

TEST_F(OutputFolder, TheOutputOptionIsParsedCarefully)
{
  const auto before = contents();
  expect_refused(compax("contact -o \"\""),
                 {"option '-o' needs a folder name; got an empty one"},
                 before);
  expect_refused(compax("contact -o --check"),
                 {"option '-o' needs a folder name after it; got the option "
                  "'--check'"},
                 before);
  expect_refused(compax("contact -o"),
                 {"option '-o' needs a folder name after it"},
                 before);
  expect_refused(compax("contact -o a -o b"),
                 {"option '-o' given twice (OUTDIR 'a' and 'b')"},
                 before);
  // --check checks OUTDIR too, and creates nothing.
  expect_refused(compax("contact --check -o ."), {"working folder"}, before);
  const auto check = compax("contact --check -o fresh");
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(contents(), before);
}

TEST_F(OutputFolder, HelpStatesTheRules)
{
  for (const std::string call : {"--help", "contact --help"})
    {
      const auto r = compax(call);
      EXPECT_EQ(r.exit_code, 0);
      EXPECT_NE(r.out.find("never deletes or overwrites what it did not "
                           "write"),
                r.out.npos)
        << r.out;
      EXPECT_NE(r.out.find("--overwrite"), r.out.npos);
      EXPECT_NE(r.out.find(".<OUTDIR>.lock"), r.out.npos);
    }
}

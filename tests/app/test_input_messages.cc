// Issue #14, Why 5: the smaller gaps. Every bad input exits 2 with one line
// naming the entry, its value and the reason, and leaves nothing behind;
// --check opens the files the parameters name; --print-parameters states
// what every entry allows; timing stays out of the result CSVs, so two runs
// of one input give byte-identical results.

#include "app_test_support.h"

#include <unistd.h>

#include <sstream>

using compax::testing::AppTest;

class InputMessages : public AppTest
{
};

TEST_F(InputMessages, LogNormalSigmaTooWideForTheDieIsBadInput)
{
  write("bad.prm", "subsection Packing\n set Log-normal sigma = 50\nend\n");
  const auto before = contents();
  for (const std::string call : {"die bad.prm -o out", "die bad.prm --check"})
    expect_refused(compax(call),
                   {"entry 'Packing/Log-normal sigma' = 50: the largest "
                    "radius the packing may draw",
                    "must be below a quarter of the die diameter"},
                   before);
  // Cut-offs that keep almost no radius.
  write("bad.prm",
        "subsection Packing\n set Log-normal sigma = 0.1\n"
        " set Minimum radius = 1e-3\n set Maximum radius = 2e-3\nend\n");
  expect_refused(compax("die bad.prm --check"),
                 {"entry 'Packing/Minimum radius' = 0.001: the cut-offs"},
                 contents());
}

TEST_F(InputMessages, NumbersThatADoubleCannotHoldAreBadInput)
{
  // A pattern of compax (Force tolerance) and one of deal.II (a list of
  // doubles): 1e-320 under- and 1e999 overflows a double.
  write("bad.prm", "set Force tolerance = 1e-320\n");
  expect_refused(compax("bed bad.prm --check"),
                 {"The entry value 1e-320 for the entry named Force tolerance "
                  "does not match the given pattern: [Real number in (0, 1]]"},
                 contents());
  write("bad.prm",
        "subsection Protocol\n set Unloading points = 0.7, 1e-320\nend\n");
  expect_refused(compax("die bad.prm -o out"),
                 {"entry 'Protocol/Unloading points' = 0.7, 1e-320: '1e-320' "
                  "is not representable as a double"},
                 contents());
  write("bad.prm", "subsection Packing\n set Die diameter = 1e999\nend\n");
  expect_refused(compax("die bad.prm --check"), {"Die diameter"}, contents());
}

TEST_F(InputMessages, BranchDensitiesMessageShowsTheValue)
{
  write("bad.prm",
        "subsection Paths\n set Branch densities = 0.80, 0.75\nend\n");
  expect_refused(compax("database bad.prm -o out"),
                 {"entry 'Paths/Branch densities' = 0.80, 0.75: increasing "
                  "densities"},
                 contents());
}

TEST_F(InputMessages, CalibrateBoundsBlameTheBounds)
{
  write("bad.prm",
        "subsection Calibration\n set Fitted parameters = beta\n"
        " set Initial values = 0.5\n set Lower bounds = 2\n"
        " set Upper bounds = 1\nend\n");
  expect_refused(compax("calibrate bad.prm -o out"),
                 {"entry 'Calibration/Lower bounds' = 2: the lower bound of "
                  "beta (2) must be below its upper bound (1)"},
                 contents());
  write("bad.prm",
        "subsection Calibration\n set Fitted parameters = beta\n"
        " set Initial values = 0.5\n set Lower bounds = 0, 0\n"
        " set Upper bounds = 1\nend\n");
  expect_refused(compax("calibrate bad.prm -o out"),
                 {"entry 'Calibration/Lower bounds' = 0, 0: give one value "
                  "per fitted parameter (1)"},
                 contents());
  // --check reads the measured curve.
  write("bad.prm",
        "subsection Calibration\n set Measured curve = missing.csv\nend\n");
  expect_refused(compax("calibrate bad.prm --check"),
                 {"entry 'Calibration/Measured curve' = missing.csv: no such "
                  "file"},
                 contents());
}

TEST_F(InputMessages, AMeshFileThatIsAFolderIsNamedAsSuch)
{
  std::filesystem::create_directories(folder / "meshes");
  write("bad.prm", "subsection Geometry\n set Mesh file = meshes\nend\n");
  expect_refused(compax("tablet bad.prm -o out"),
                 {"entry 'Geometry/Mesh file' = meshes: is a folder"},
                 contents());
}

TEST_F(InputMessages, AParameterFileThatCannotBeReadIsNotCalledMissing)
{
  std::filesystem::create_directories(folder / "folder.prm");
  expect_refused(compax("contact folder.prm -o out"),
                 {"parameter file 'folder.prm' is a folder, not a file"},
                 contents());
  expect_refused(compax("contact missing.prm -o out"),
                 {"parameter file 'missing.prm' does not exist"},
                 contents());
  // A file without read permission, read by an unprivileged user (root
  // reads everything).
  write("locked.prm", "# the defaults\n");
  std::filesystem::permissions(folder / "locked.prm",
                               std::filesystem::perms::none);
  std::filesystem::permissions(folder,
                               std::filesystem::perms::all,
                               std::filesystem::perm_options::add);
  const auto        before = contents();
  const std::string as_user
    = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups "
                       : "";
  const auto r
    = shell(as_user + "'" + COMPAX_EXECUTABLE + "' contact locked.prm --check");
  if (r.err.find("setpriv") != std::string::npos)
    GTEST_SKIP() << "cannot drop privileges: " << r.err;
  expect_refused(r,
                 {"parameter file 'locked.prm' cannot be read (Permission "
                  "denied)"},
                 before);
}

TEST_F(InputMessages, CheckOpensTheFilesTheParametersName)
{
  write("notes.txt", "not a checkpoint\n");
  const auto before = contents();
  // Checkpoints of every resumable command, and the tables they read.
  const std::vector<std::pair<std::string, std::string>> cases{
    {"die", "subsection Protocol\n set Resume from = notes.txt\nend\n"},
    {"die", "subsection Protocol\n set Rerun branch from = notes.txt\nend\n"},
    {"rve", "subsection Checkpoints\n set Resume from = notes.txt\nend\n"},
    {"database",
     "subsection Checkpoints\n set Resume from = notes.txt\nend\n"}};
  for (const auto &[command, text] : cases)
    {
      write("bad.prm", text);
      const auto with_prm = contents();
      const auto run      = compax(command + " bad.prm -o out");
      const auto check    = compax(command + " bad.prm --check");
      expect_refused(check, {"notes.txt: is not a compax archive"}, with_prm);
      expect_refused(run, {"notes.txt: is not a compax archive"}, with_prm);
      EXPECT_EQ(check.err, run.err);
    }
  write("bad.prm", "subsection Material\n set DPC table = notes.txt\nend\n");
  expect_refused(compax("tablet bad.prm --check"),
                 {"entry 'Material/DPC table' = notes.txt"},
                 contents());
  write("bad.prm", "subsection Output\n set Resume from = nowhere\nend\n");
  expect_refused(compax("tablet bad.prm --check"),
                 {"entry 'Output/Resume from' = nowhere: no such folder"},
                 contents());
  write("bad.prm",
        "subsection Strain path\n set Path = csv\n"
        " set Strain increments file = notes.txt\nend\n");
  expect_refused(compax("rve bad.prm --check"),
                 {"Strain path/Strain increments file"},
                 contents());
  std::filesystem::remove(folder / "bad.prm");
  EXPECT_EQ(contents(), before);
}

TEST_F(InputMessages, PrintParametersShowsWhatEveryEntryAllows)
{
  for (const std::string &command : compax::testing::parameter_commands)
    {
      const auto r = compax(command + " --print-parameters");
      ASSERT_EQ(r.exit_code, 0) << command;
      std::istringstream lines(r.out);
      bool               allowed = false;
      int                entries = 0;
      for (std::string line; std::getline(lines, line);)
        {
          const auto first = line.find_first_not_of(' ');
          if (first == std::string::npos)
            continue;
          if (line[first] == '#')
            allowed = allowed || line.find("Allowed:") != std::string::npos;
          else
            {
              if (line.compare(first, 4, "set ") == 0)
                {
                  ++entries;
                  EXPECT_TRUE(allowed) << command << ": " << line;
                }
              allowed = false;
            }
        }
      EXPECT_GT(entries, 3) << command;
      // The printed file is a valid parameter file.
      write(command + ".prm", r.out);
      EXPECT_EQ(compax(command + " " + command + ".prm --check").exit_code, 0)
        << command;
    }
  // Integer ranges in particular.
  const auto die = compax("die --print-parameters");
  EXPECT_NE(die.out.find("# Allowed: an integer in [1, 10000000].\n"
                         "  set Number of particles"),
            std::string::npos);
  EXPECT_NE(die.out.find("# Allowed: an integer in [0, inf).\n  set Seed"),
            std::string::npos);
}

TEST_F(InputMessages, TwoRunsOfOneInputGiveTheSameResultFiles)
{
  write("die.prm",
        "subsection Packing\n set Number of particles = 60\n"
        " set Die diameter = 2e-3\nend\n"
        "subsection Protocol\n set Final relative density = 0.66\n"
        " set Compaction steps = 4\n set Unloading points = 0.66\n"
        " set Checkpoint interval = 2\nend\n");
  write("rve.prm",
        "subsection Packing\n set Number of particles = 60\n set Seed = 4\n"
        "end\nsubsection Strain path\n set Target relative density = 0.7\n"
        " set Loading steps = 4\n set Unloading strain step = 5e-3\nend\n"
        "subsection Output\n set Finite-difference check interval = 2\n"
        "end\n");
  for (const std::string command : {"die", "rve"})
    {
      ASSERT_EQ(compax(command + " " + command + ".prm -o a").exit_code, 0);
      ASSERT_EQ(compax(command + " " + command + ".prm -o b").exit_code, 0);
      std::size_t compared = 0;
      for (const auto &e :
           std::filesystem::recursive_directory_iterator(folder / "a"))
        {
          if (!e.is_regular_file())
            continue;
          const auto relative = e.path().lexically_relative(folder / "a");
          if (relative == "timing.csv")
            continue;
          EXPECT_TRUE(read(e.path()) == read(folder / "b" / relative))
            << command << ": " << relative << " differs";
          ++compared;
        }
      EXPECT_GT(compared, 5u);
      // The times are in timing.csv, which differs.
      const std::string timing = read(folder / "a" / "timing.csv");
      EXPECT_EQ(timing.rfind(command == "die"
                               ? "stage,branch,step,wall_seconds\n"
                               : "step,stage,step_seconds,tangent_seconds\n",
                             0),
                0u)
        << timing;
      for (const char *csv : {"die.csv", "rve.csv", "moduli.csv"})
        {
          if (std::filesystem::exists(folder / "a" / csv))
            {
              EXPECT_EQ(read(folder / "a" / csv).find("seconds"),
                        std::string::npos)
                << csv;
            }
        }
      std::filesystem::remove_all(folder / "a");
      std::filesystem::remove_all(folder / "b");
    }
}

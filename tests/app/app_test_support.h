#pragma once

// Runs the real `compax` executable in a fresh folder and reads what it
// wrote, for the application tests.

#include "tests/support/temporary_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace compax::testing
{
  /// What one run of the executable produced.
  struct RunResult
  {
    int         exit_code;
    std::string out;
    std::string err;
  };

  /// A fresh working folder per test (TemporaryFolderTest's), removed
  /// afterwards, in which the executable runs.
  class AppTest : public TemporaryFolderTest
  {
  protected:
    /// Runs `compax <arguments>` in the test folder.
    RunResult
    compax(const std::string &arguments) const
    {
      return shell("'" + std::string(COMPAX_EXECUTABLE) + "' " + arguments);
    }

    /// Starts `compax <arguments>` in the background in the test folder
    /// (its output goes to @p log) and returns its process id.
    pid_t
    start(const std::string &arguments, const std::string &log) const
    {
      const auto pid_file = folder / "pid";
      std::filesystem::remove(pid_file);
      const std::string line = "cd '" + folder.string() + "' && ('"
                               + COMPAX_EXECUTABLE + "' " + arguments + " > '"
                               + log + "' 2>&1 & echo $! > '"
                               + pid_file.string() + "')";
      EXPECT_EQ(std::system(line.c_str()), 0);
      pid_t pid = 0;
      for (int k = 0; k < 500 && pid <= 0; ++k)
        {
          std::ifstream(pid_file) >> pid;
          if (pid <= 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
      std::filesystem::remove(pid_file);
      return pid;
    }

    /// Runs a shell command line in the test folder (the executable is
    /// COMPAX_EXECUTABLE), e.g. with environment variables.
    RunResult
    shell(const std::string &command) const
    {
      const auto out = folder / "stdout.txt", err = folder / "stderr.txt";
      const std::string line = "cd '" + folder.string() + "' && " + command
                               + " > '" + out.string() + "' 2> '" + err.string()
                               + "'";
      const int status = std::system(line.c_str());
      RunResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                  read(out),
                  read(err)};
      std::filesystem::remove(out);
      std::filesystem::remove(err);
      return r;
    }

    /// Every file below the test folder (relative path and content) and
    /// every folder (path and '/'): what was there before a run must be
    /// there after it, unchanged.
    std::map<std::string, std::string>
    contents() const
    {
      std::map<std::string, std::string> files;
      for (const auto &e :
           std::filesystem::recursive_directory_iterator(folder))
        if (e.is_regular_file())
          files[e.path().lexically_relative(folder).string()] = read(e.path());
        else
          files[e.path().lexically_relative(folder).string() + "/"] = "";
      return files;
    }

    /// Bad input that leaves everything as it was: exit code 2, one stderr
    /// line that contains every piece of `expected` and no MPI_ABORT text,
    /// and exactly the files of `before` (no staging folder, lock file or
    /// output folder left behind).
    void
    expect_refused(const RunResult                          &r,
                   const std::vector<std::string>           &expected,
                   const std::map<std::string, std::string> &before) const
    {
      EXPECT_EQ(r.exit_code, 2) << r.err << r.out;
      for (const std::string &piece : expected)
        EXPECT_NE(r.err.find(piece), std::string::npos)
          << "expected '" << piece << "' in stderr: " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_EQ(r.err.find("MPI_ABORT"), std::string::npos) << r.err;
      EXPECT_EQ(contents(), before);
      std::vector<std::string> left;
      for (const auto &e :
           std::filesystem::recursive_directory_iterator(folder))
        {
          const std::string name = e.path().filename().string();
          if (name.find(".partial-") != std::string::npos
              || (name.size() > 5 && name.rfind(".lock") == name.size() - 5))
            left.push_back(name);
        }
      EXPECT_TRUE(left.empty()) << left.front();
    }

    /// Refused input that writes nothing: exit code 2, stderr names every
    /// piece of @p expected, and the output folder @p out does not exist.
    void
    expect_refused_without_output(const RunResult                &r,
                                  const std::vector<std::string> &expected,
                                  const std::string &out = "out") const
    {
      EXPECT_EQ(r.exit_code, 2);
      for (const std::string &piece : expected)
        EXPECT_NE(r.err.find(piece), std::string::npos) << r.err;
      EXPECT_FALSE(std::filesystem::exists(folder / out));
    }

    /// Writes a file in the test folder.
    void
    write(const std::string &name, const std::string &text) const
    {
      std::ofstream(folder / name) << text;
    }

    static std::string
    read(const std::filesystem::path &file)
    {
      std::ifstream      in(file);
      std::ostringstream text;
      text << in.rdbuf();
      return text.str();
    }

    /// Bad input: exit code 2, one stderr line that contains `expected`, and
    /// nothing in the test folder but the parameter file `bad.prm`.
    void
    expect_rejected(const RunResult &r, const std::string &expected) const
    {
      EXPECT_EQ(r.exit_code, 2);
      EXPECT_NE(r.err.find(expected), std::string::npos) << "stderr: " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_EQ(entries(), std::vector<std::string>{"bad.prm"});
    }

    /// `compax <command>` refuses the parameter file @p prm (written as
    /// `bad.prm`) as expect_rejected says.
    void
    expect_prm_rejected(const std::string &command,
                        const std::string &prm,
                        const std::string &expected) const
    {
      write("bad.prm", prm);
      expect_rejected(compax(command + " bad.prm -o out"), expected);
    }

    /// Names in the test folder (for "no half-written output" checks).
    std::vector<std::string>
    entries() const
    {
      std::vector<std::string> names;
      for (const auto &e : std::filesystem::directory_iterator(folder))
        names.push_back(e.path().filename().string());
      return names;
    }

    /// The test folder (the working directory of every run).
    const std::filesystem::path &folder = dir;
  };

  /// One row of a command's table of refused parameter files: the name of
  /// the test, the file, and a piece of the one-line error message.
  struct BadInput
  {
    const char *name;
    const char *prm;
    const char *expected_in_message;
  };

  /// The test name of a BadInput row (INSTANTIATE_TEST_SUITE_P's namer).
  inline std::string
  bad_input_name(const ::testing::TestParamInfo<BadInput> &info)
  {
    return info.param.name;
  }

  /// A command's table of refused parameter files, one test per row.
  class BadInputTest : public AppTest,
                       public ::testing::WithParamInterface<BadInput>
  {
  protected:
    /// `compax <command>` refuses the row's file with exit code 2, its
    /// message in one stderr line, and no output.
    void
    expect_row_rejected(const std::string &command) const
    {
      const BadInput &bad = GetParam();
      expect_prm_rejected(command, bad.prm, bad.expected_in_message);
    }
  };

  /// Every command that reads a parameter file, in the order of
  /// `compax --help` (docs takes none).
  inline const std::vector<std::string> parameter_commands{"contact",
                                                           "die",
                                                           "jamming",
                                                           "crystal",
                                                           "mcdem",
                                                           "calibrate",
                                                           "tablet",
                                                           "rve",
                                                           "database",
                                                           "bed",
                                                           "compare"};

  /// A die study of a few seconds: 60 particles in a 2 mm die, 7
  /// compaction targets with the unloading points 0.62 (target 5) and 0.7
  /// (target 7), checkpoints after targets 2, 4 and 6.
  inline const std::string small_die_study
    = "subsection Packing\n"
      " set Number of particles = 60\n"
      " set Die diameter = 2e-3\n"
      "end\n"
      "subsection Protocol\n"
      " set Final relative density = 0.7\n"
      " set Compaction steps = 6\n"
      " set Unloading points = 0.62, 0.7\n"
      " set Checkpoint interval = 2\n"
      "end\n";

  /// The die study of the die command and resume tests: 150 particles in
  /// a 3 mm die, 16 density steps to 0.8 plus the unloading point 0.72 (17
  /// targets; 0.72 is the 13th); @p extra_protocol ends its Protocol
  /// subsection.
  inline std::string
  die_study_150(const std::string &extra_protocol = "")
  {
    return "subsection Packing\n"
           " set Number of particles = 150\n"
           " set Die diameter = 3e-3\n"
           "end\n"
           "subsection Protocol\n"
           " set Final relative density = 0.8\n"
           " set Compaction steps = 16\n"
           " set Unloading points = 0.72, 0.8\n"
           + extra_protocol + "end\n";
  }

  /// A CSV file as its header and its columns by name, as numbers (NaN for
  /// text) and as text.
  struct Csv
  {
    std::vector<std::string>                        header;
    std::map<std::string, std::vector<double>>      column;
    std::map<std::string, std::vector<std::string>> text;

    explicit Csv(const std::filesystem::path &file)
    {
      std::ifstream in(file);
      std::string   line;
      std::getline(in, line);
      std::stringstream names(line);
      for (std::string name; std::getline(names, name, ',');)
        header.push_back(name);
      while (std::getline(in, line))
        {
          std::stringstream cells(line);
          std::string       cell;
          for (const auto &name : header)
            {
              std::getline(cells, cell, ',');
              text[name].push_back(cell);
              char        *end   = nullptr;
              const double value = std::strtod(cell.c_str(), &end);
              column[name].push_back(
                cell.empty() ? 0.0
                : end == cell.c_str() + cell.size()
                  ? value
                  : std::numeric_limits<double>::quiet_NaN());
            }
        }
    }

    std::size_t
    rows() const
    {
      return column.empty() ? 0 : column.begin()->second.size();
    }

    /// Whether the header names @p name.
    bool
    has(const std::string &name) const
    {
      return std::find(header.begin(), header.end(), name) != header.end();
    }
  };

  /// The header of @p csv names every one of @p columns.
  inline void
  expect_columns(const Csv &csv, const std::vector<std::string> &columns)
  {
    for (const std::string &column : columns)
      EXPECT_TRUE(csv.has(column)) << column;
  }

  /// A resumed run repeats the uninterrupted one: equal rows (bitwise, the
  /// same binary takes the same path) of @p columns from row @p first on.
  inline void
  expect_equal_rows(const Csv                      &full,
                    const Csv                      &resumed,
                    const std::vector<std::string> &columns,
                    const std::size_t               first)
  {
    ASSERT_EQ(full.rows(), resumed.rows());
    for (const std::string &column : columns)
      for (std::size_t k = first; k < full.rows(); ++k)
        EXPECT_DOUBLE_EQ(full.column.at(column)[k],
                         resumed.column.at(column)[k])
          << column << " row " << k;
  }

  /// A frictionless die carries no axial load: at equilibrium the punches
  /// of every die.csv row carry the same force, to @p relative times the
  /// largest upper-punch force, which must be positive.
  inline void
  expect_balanced_punches(const Csv &die, const double relative = 1e-4)
  {
    const auto &upper = die.column.at("upper_punch_force");
    const auto &lower = die.column.at("lower_punch_force");
    double      peak  = 0;
    for (double f : upper)
      peak = std::max(peak, f);
    ASSERT_GT(peak, 0.0);
    for (std::size_t i = 0; i < die.rows(); ++i)
      EXPECT_NEAR(upper[i], lower[i], relative * peak) << "row " << i;
  }

  /// Last value of `column` in the rows of the given `stage` (0 if the
  /// stage has no row).
  inline double
  last_in_stage(const Csv         &csv,
                const std::string &stage,
                const std::string &column)
  {
    double value = 0.0;
    for (std::size_t i = 0; i < csv.rows(); ++i)
      if (csv.text.at("stage")[i] == stage)
        value = csv.column.at(column)[i];
    return value;
  }

  /// The subsection Contact of a parameter file with the given contact law
  /// and formulation.
  inline std::string
  contact_subsection(const std::string &law, const std::string &formulation)
  {
    return "subsection Contact\n set Contact law = " + law
           + "\n set Formulation = " + formulation + "\nend\n";
  }
} // namespace compax::testing

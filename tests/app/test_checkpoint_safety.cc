// Issue #14, Why 2 and 3: no damaged or foreign checkpoint is trusted. A die
// run resumed from an RVE checkpoint or a branch checkpoint, from a
// truncated or damaged checkpoint, or with other parameters (particle
// radius, contact law) is refused with exit 2 and one line naming the entry
// and the reason, and so are the RVE, database and tablet alike; --check
// says the same as the run; nothing is left behind and every file is as it
// was.

#include "app_test_support.h"

#include "coupling/hdf5_archive.h"

#include <fstream>
#include <iterator>

using compax::testing::AppTest;

namespace
{
  const std::string &die_study = compax::testing::small_die_study;
}

namespace
{
  /// A short RVE path with a checkpoint every three steps.
  const std::string rve_study = "subsection Packing\n"
                                " set Number of particles = 60\n"
                                " set Seed = 4\n"
                                "end\n"
                                "subsection Strain path\n"
                                " set Target relative density = 0.7\n"
                                " set Loading steps = 6\n"
                                " set Unloading = false\n"
                                "end\n"
                                "subsection Output\n"
                                " set Tangent interval = 0\n"
                                " set Finite-difference check interval = 0\n"
                                " set Snapshot interval = 3\n"
                                "end\n"
                                "subsection Checkpoints\n"
                                " set Checkpoint interval = 3\n"
                                "end\n";

  std::string
  bytes(const std::filesystem::path &file)
  {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in),
            std::istreambuf_iterator<char>()};
  }

  void
  put(const std::filesystem::path &file, const std::string &content)
  {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << content;
  }

  /// A copy with one byte flipped at the given fraction of its length.
  std::string
  flipped(std::string content, const double where)
  {
    content[static_cast<std::size_t>(where * (content.size() - 1))] ^= 0x20;
    return content;
  }
} // namespace

class CheckpointSafety : public AppTest
{
protected:
  /// Resume `command` with `study` plus `Resume from = file` (in
  /// `subsection`), by the run and by --check: both refused alike.
  void
  expect_resume_refused(const std::string              &command,
                        const std::string              &study,
                        const std::string              &subsection,
                        const std::string              &file,
                        const std::vector<std::string> &expected)
  {
    write("resume.prm",
          study + "subsection " + subsection + "\n set Resume from = " + file
            + "\nend\n");
    const auto before = contents();
    expect_refused(compax(command + " resume.prm -o resumed"),
                   expected,
                   before);
    expect_refused(compax(command + " resume.prm --check"), expected, before);
  }

  /// The intact @p checkpoint truncated to half, and with a flipped byte
  /// at each of @p where (fractions of its length), in the test folder:
  /// refused by the run and --check, naming the entry.
  void
  expect_damage_refused(const std::string           &command,
                        const std::string           &study,
                        const std::string           &subsection,
                        const std::filesystem::path &checkpoint,
                        const std::vector<double>   &where)
  {
    const std::string entry  = "entry '" + subsection + "/Resume from' = ";
    const std::string intact = bytes(checkpoint);
    put(folder / "half.h5", intact.substr(0, intact.size() / 2));
    expect_resume_refused(command,
                          study,
                          subsection,
                          "half.h5",
                          {entry,
                           "half.h5: is truncated ("
                             + std::to_string(intact.size() / 2) + " of "
                             + std::to_string(intact.size()) + " bytes)"});
    std::filesystem::remove(folder / "half.h5");
    for (const double w : where)
      {
        put(folder / "flipped.h5", flipped(intact, w));
        expect_resume_refused(command,
                              study,
                              subsection,
                              "flipped.h5",
                              {entry,
                               "flipped.h5: fails its checksum (the file is "
                               "damaged)"});
      }
    std::filesystem::remove(folder / "flipped.h5");
  }

  /// @p file of a finished tablet run (folder `tablet`) with a flipped byte
  /// in its middle: resuming `tablet` from that run is refused with
  /// @p expected; the file is restored afterwards.
  void
  expect_tablet_file_damage_refused(const std::string           &tablet,
                                    const std::filesystem::path &file,
                                    const std::string           &expected)
  {
    const std::string intact = bytes(file);
    put(file, flipped(intact, 0.5));
    expect_resume_refused("tablet", tablet, "Output", "tablet", {expected});
    put(file, intact);
  }
};

TEST_F(CheckpointSafety, DieRefusesForeignDamagedAndMismatchedCheckpoints)
{
  write("die.prm", die_study);
  ASSERT_EQ(compax("die die.prm -o die").exit_code, 0);
  write("rve.prm", rve_study);
  ASSERT_EQ(compax("rve rve.prm -o rve").exit_code, 0);
  const auto checkpoint   = folder / "die" / "checkpoints" / "compaction.h5";
  const std::string entry = "entry 'Protocol/Resume from' = ";

  // Foreign kinds: an RVE checkpoint, a branch checkpoint.
  expect_resume_refused("die",
                        die_study,
                        "Protocol",
                        "rve/checkpoints/rve.h5",
                        {entry
                         + "rve/checkpoints/rve.h5: is of kind 'rve' "
                           "(RVE checkpoint), not 'die-compaction' (die "
                           "compaction checkpoint)"});
  expect_resume_refused("die",
                        die_study,
                        "Protocol",
                        "die/checkpoints/branch-1.h5",
                        {entry
                         + "die/checkpoints/branch-1.h5: is of kind "
                           "'die-branch'"});

  // Truncated to half, and a flipped byte in the data and near the end
  // (where HDF5 keeps attributes).
  expect_damage_refused(
    "die", die_study, "Protocol", checkpoint, {0.3, 0.6, 0.97});

  // Other parameters: the first differing entry with both values.
  expect_resume_refused(
    "die",
    die_study + "subsection Material\n set Radius = 2.4e-4\nend\n",
    "Protocol",
    "die/checkpoints/compaction.h5",
    {entry,
     "was written with other parameters: Material/Radius = 0.00022 in the "
     "archive, 0.00024 here"});
  expect_resume_refused(
    "die",
    die_study + "subsection Contact\n set Contact law = elastic\nend\n",
    "Protocol",
    "die/checkpoints/compaction.h5",
    {"Contact/Contact law = bonded-elastoplastic in the archive, elastic "
     "here"});

  // A branch rerun checks its state the same way.
  write("rerun.prm",
        die_study
          + "subsection Material\n set Radius = 2.4e-4\nend\n"
            "subsection Protocol\n set Rerun branch from = "
            "die/checkpoints/compaction.h5\nend\n");
  const auto before = contents();
  expect_refused(compax("die rerun.prm -o rerun"),
                 {"entry 'Protocol/Rerun branch from' = "
                  "die/checkpoints/compaction.h5: is of kind "
                  "'die-compaction'"},
                 before);

  // A checkpoint moved away from its run folder cannot bring the earlier
  // branches' files along.
  std::filesystem::copy_file(checkpoint, folder / "alone.h5");
  expect_resume_refused("die",
                        die_study,
                        "Protocol",
                        "alone.h5",
                        {entry
                         + "alone.h5: the earlier branches' file "
                           "'snapshots/compaction-1.vtu' is not next to "
                           "the checkpoint"});
}

TEST_F(CheckpointSafety, OldFormatFilesAreRefused)
{
  write("die.prm", die_study);
  const hid_t file = H5Fcreate((folder / "old.h5").c_str(),
                               H5F_ACC_TRUNC,
                               H5P_DEFAULT,
                               H5P_DEFAULT);
  ASSERT_GE(file, 0);
  H5Fclose(file);
  expect_resume_refused("die",
                        die_study,
                        "Protocol",
                        "old.h5",
                        {"entry 'Protocol/Resume from' = old.h5: is an HDF5 "
                         "file without the compax archive header"});
  expect_resume_refused("die",
                        die_study,
                        "Protocol",
                        "die.prm",
                        {"die.prm: is not a compax archive"});
}

TEST_F(CheckpointSafety, RveRefusesForeignDamagedAndMismatchedCheckpoints)
{
  write("rve.prm", rve_study);
  ASSERT_EQ(compax("rve rve.prm -o rve").exit_code, 0);
  write("die.prm", die_study);
  ASSERT_EQ(compax("die die.prm -o die").exit_code, 0);
  const std::string entry = "entry 'Checkpoints/Resume from' = ";
  const auto        file  = folder / "rve" / "checkpoints" / "rve.h5";

  expect_resume_refused("rve",
                        rve_study,
                        "Checkpoints",
                        "die/checkpoints/compaction.h5",
                        {"is of kind 'die-compaction' (die compaction "
                         "checkpoint), not 'rve' (RVE checkpoint)"});
  expect_damage_refused("rve", rve_study, "Checkpoints", file, {0.5});
  expect_resume_refused(
    "rve",
    rve_study + "subsection Material\n set Young's modulus = 6e9\nend\n",
    "Checkpoints",
    "rve/checkpoints/rve.h5",
    {entry,
     "was written with other parameters: Material/Young's modulus = "
     "5000000000 in the archive, 6000000000 here"});
  expect_resume_refused(
    "rve",
    rve_study + "subsection Contact\n set Contact law = elastic\nend\n",
    "Checkpoints",
    "rve/checkpoints/rve.h5",
    {"Contact/Contact law = bonded-elastoplastic in the archive, elastic "
     "here"});
}

TEST_F(CheckpointSafety, DatabaseAndTabletRefuseForeignAndDamagedCheckpoints)
{
  write("die.prm", die_study);
  ASSERT_EQ(compax("die die.prm -o die").exit_code, 0);
  expect_resume_refused("database",
                        "",
                        "Checkpoints",
                        "die/checkpoints/compaction.h5",
                        {"entry 'Checkpoints/Resume from' = ",
                         "is of kind 'die-compaction' (die compaction "
                         "checkpoint), not 'database-checkpoint'"});

  // A tiny tablet cycle with a checkpoint every two steps.
  const std::string tablet
    = "subsection Mesh\n  set Radial cells = 2\nend\n"
      "subsection Process\n  set Compaction steps = 4\n"
      "  set Unloading steps = 2\n  set Ejection steps = 0\nend\n"
      "subsection Output\n  set Checkpoint interval = 2\n"
      "  set Write fields = false\nend\n";
  write("tablet.prm", tablet);
  ASSERT_EQ(compax("tablet tablet.prm -o tablet").exit_code, 0);
  expect_tablet_file_damage_refused(
    tablet,
    folder / "tablet" / "checkpoint" / "tablet.h5",
    "entry 'Output/Resume from' = tablet: checkpoint/tablet.h5 fails its "
    "checksum");
  // The solver state it lists, damaged.
  expect_tablet_file_damage_refused(
    tablet,
    folder / "tablet" / "checkpoint" / "solver.0.bin",
    "its file 'solver.0.bin' differs from the one it was written with");
  expect_resume_refused(
    "tablet",
    tablet + "subsection Die\n  set Wall friction coefficient = 0.3\nend\n",
    "Output",
    "tablet",
    {"Die/Wall friction coefficient = 0.25 in the archive, 0.3 here"});
  expect_resume_refused("tablet",
                        tablet,
                        "Output",
                        "die",
                        {"entry 'Output/Resume from' = die: has no checkpoint "
                         "folder"});
}

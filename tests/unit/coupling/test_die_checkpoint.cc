// A dem::DieStudy checkpointed to and resumed from the die archives of
// coupling, without the command line: the checkpoint reads back what was
// written, the resumed study gives the rows of the uninterrupted one, and
// another study's parameters or a branch checkpoint are refused.

#include "coupling/die_checkpoint.h"
#include "coupling/die_state_archive.h"
#include "coupling/hdf5_archive.h"
#include "dem/die/die_study.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <unistd.h>

using namespace compax;

namespace
{
  /// 100 spheres in a 3 mm die to rho = 0.72 in 6 steps, one branch at
  /// the end, a checkpoint every 2 targets.
  dem::DieStudyOptions
  small_study()
  {
    dem::DieStudyOptions o;
    o.deposition.n_particles       = 100;
    o.deposition.die_diameter      = 3e-3;
    o.deposition.seed              = 3;
    o.final_density                = 0.72;
    o.compaction_steps             = 6;
    o.protocol.unloading_points    = {0.72};
    o.protocol.checkpoint_interval = 2;
    return o;
  }

  std::string
  temporary(const std::string &name)
  {
    return (std::filesystem::temp_directory_path()
            / ("compax-" + std::to_string(::getpid()) + "-" + name))
      .string();
  }

  /// Same numbers, NaN equal to NaN.
  void
  expect_same(const double a, const double b, const std::size_t row)
  {
    if (std::isnan(a))
      EXPECT_TRUE(std::isnan(b)) << "row " << row;
    else
      EXPECT_EQ(a, b) << "row " << row;
  }
} // namespace

TEST(DieCheckpoint, StudyResumedFromItsCheckpointFileEqualsTheUninterrupted)
{
  const dem::ContactModel   model = compax::testing::material1::contact_model();
  const dem::DieStudyResult full  = dem::DieStudy(model, small_study()).run();
  const std::string         file  = temporary("compaction.h5");
  const std::string         parameters = "Protocol/Steps = 6\n";
  coupling::DieBranchFiles  files;
  files.fabric_rows = "1,compaction,0.72\n";
  files.files       = {{"snapshots/compaction-1.vtu", "0123456789abcdef"}};

  // Interrupted after 4 of the 6 targets, the last checkpoint in a file.
  dem::DieStudyOptions stopping = small_study();
  stopping.protocol.stop_after  = 4;
  dem::DieStudyObserver           observer;
  std::optional<dem::DieProgress> written;
  observer.checkpoint = [&](const dem::Bed &bed, const dem::DieProgress &p) {
    coupling::write_die_checkpoint(file, parameters, bed, p, files);
    written = p;
  };
  ASSERT_TRUE(dem::DieStudy(model, stopping).run(observer).stopped);
  ASSERT_TRUE(written.has_value());

  EXPECT_THROW(coupling::read_die_checkpoint(file,
                                             "Protocol/Steps = 7\n",
                                             model),
               coupling::Hdf5ArchiveError);
  coupling::DieCheckpoint c
    = coupling::read_die_checkpoint(file, parameters, model);
  std::filesystem::remove(file);
  EXPECT_EQ(c.progress.completed_targets, written->completed_targets);
  EXPECT_EQ(c.progress.compaction_targets, written->compaction_targets);
  ASSERT_EQ(c.progress.rows.size(), written->rows.size());
  for (std::size_t i = 0; i < c.progress.rows.size(); ++i)
    {
      EXPECT_EQ(c.progress.rows[i].stage, written->rows[i].stage);
      expect_same(c.progress.rows[i].upper_punch_pressure,
                  written->rows[i].upper_punch_pressure,
                  i);
      expect_same(c.progress.rows[i].sigma_zz_interior,
                  written->rows[i].sigma_zz_interior,
                  i);
    }
  EXPECT_EQ(c.branch_files.fabric_rows, files.fabric_rows);
  EXPECT_EQ(c.branch_files.files, files.files);

  dem::DieStudy resumed(model,
                        small_study(),
                        dem::DieStudyStart::resume(std::move(c.bed),
                                                   std::move(c.progress)));
  ASSERT_EQ(resumed.resume_mismatch(), "");
  const dem::DieStudyResult second = resumed.run();
  ASSERT_TRUE(second.converged) << second.failure;
  ASSERT_EQ(second.rows.size(), full.rows.size());
  for (std::size_t i = 0; i < full.rows.size(); ++i)
    {
      EXPECT_EQ(second.rows[i].stage, full.rows[i].stage) << "row " << i;
      expect_same(second.rows[i].relative_density,
                  full.rows[i].relative_density,
                  i);
      expect_same(second.rows[i].upper_punch_pressure,
                  full.rows[i].upper_punch_pressure,
                  i);
      expect_same(second.rows[i].die_wall_pressure,
                  full.rows[i].die_wall_pressure,
                  i);
    }
}

TEST(DieCheckpoint, BranchCheckpointKeepsTheBedAndItsBranch)
{
  const dem::ContactModel model  = compax::testing::material1::contact_model();
  dem::DieStudyOptions    o      = small_study();
  o.protocol.stop_after          = 1;
  o.protocol.checkpoint_interval = 1;
  dem::DieStudyObserver   observer;
  std::optional<dem::Bed> bed;
  observer.checkpoint
    = [&](const dem::Bed &b, const dem::DieProgress &) { bed = b; };
  dem::DieStudy(model, o).run(observer);
  ASSERT_TRUE(bed.has_value());

  const std::string file = temporary("branch-3.h5");
  coupling::write_die_branch_checkpoint(file, "", *bed, 3);
  EXPECT_THROW(coupling::read_die_checkpoint(file, "", model),
               coupling::Hdf5ArchiveError);
  const coupling::DieBranchState state
    = coupling::read_die_branch_checkpoint(file, "", model);
  std::filesystem::remove(file);
  EXPECT_EQ(state.branch, 3);
  ASSERT_EQ(state.bed.particles.size(), bed->particles.size());
  for (std::size_t i = 0; i < bed->particles.size(); ++i)
    EXPECT_EQ(state.bed.particles.positions[i], bed->particles.positions[i]);
}

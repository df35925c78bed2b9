// HDF5 checkpoints of a compacted bed: the restored state is bit-identical,
// and continuing the compaction from the restored state gives the same
// result as continuing the original (restart equals an uninterrupted run).

#include "coupling/bed_archive.h"
#include "dem/die/die_setup.h"
#include "dem/solver/load_stepper.h"
#include "tests/support/deposited_die.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using namespace compax;

namespace
{
  dem::Bed
  compacted_bed(dem::LoadStepper &stepper)
  {
    dem::Bed bed = compax::testing::deposited_die(60, 2.2e-3, 7);
    // Press well into the jammed regime so that plastic radii and bridges
    // exist.
    for (const double rho : {0.62, 0.68, 0.72})
      {
        dem::DieWalls target = bed.walls;
        target.upper_punch
          = bed.walls.lower_punch
            + bed.particles.solid_volume() / (bed.walls.punch_area() * rho);
        EXPECT_TRUE(stepper.advance(bed, target).converged);
      }
    return bed;
  }
} // namespace

TEST(BedCheckpoint, RestartEqualsUninterruptedRun)
{
  const dem::ContactModel model = compax::testing::material1::contact_model();
  dem::LoadStepper        stepper(model);
  dem::Bed                original = compacted_bed(stepper);

  const std::string file
    = (std::filesystem::temp_directory_path()
       / ("compax-bed-" + std::to_string(::getpid()) + ".h5"))
        .string();
  {
    coupling::Hdf5ArchiveWriter writer(file, {"test", ""});
    coupling::save_bed(writer, "state", original);
    writer.commit();
  }
  const coupling::Hdf5ArchiveReader reader(file);
  dem::Bed restored = coupling::load_bed(reader, "state", model);
  std::filesystem::remove(file);

  ASSERT_EQ(restored.particles.size(), original.particles.size());
  for (std::size_t i = 0; i < original.particles.size(); ++i)
    EXPECT_EQ(restored.particles.positions[i], original.particles.positions[i]);
  std::size_t with_history = 0;
  double      sum_a_p = 0, restored_sum_a_p = 0;
  for (const auto &c : original.contacts.pairs)
    {
      with_history += c.history.a_p > 0;
      sum_a_p += c.history.a_p;
    }
  for (const auto &c : restored.contacts.pairs)
    restored_sum_a_p += c.history.a_p;
  ASSERT_GT(with_history, 10u);
  EXPECT_EQ(restored_sum_a_p, sum_a_p);

  // One more load step from each.
  dem::DieWalls target = original.walls;
  target.upper_punch -= 0.01 * original.walls.height();
  dem::LoadStepper stepper_a(model), stepper_b(model);
  ASSERT_TRUE(stepper_a.advance(original, target).converged);
  ASSERT_TRUE(stepper_b.advance(restored, target).converged);
  const double R = original.particles.mean_radius();
  for (std::size_t i = 0; i < original.particles.size(); ++i)
    EXPECT_LT((restored.particles.positions[i]
               - original.particles.positions[i])
                .norm(),
              1e-9 * R);
}

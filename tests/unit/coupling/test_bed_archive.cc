// HDF5 checkpoints of a compacted bed: the restored state is bit-identical,
// and continuing the compaction from the restored state gives the same
// result as continuing the original (restart equals an uninterrupted run).

#include "coupling/bed_archive.h"
#include "dem/die/die_setup.h"
#include "dem/solver/load_stepper.h"
#include "tests/support/deposited_die.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/walton_braun_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <unistd.h>
#include <utility>

using namespace compax;

namespace
{
  /// A temporary HDF5 file name of this process.
  std::string
  temporary_archive()
  {
    return (std::filesystem::temp_directory_path()
            / ("compax-bed-" + std::to_string(::getpid()) + ".h5"))
      .string();
  }

  /// @p bed written to an archive and read back with @p model.
  dem::Bed
  restart(const dem::Bed &bed, const dem::ContactModel &model)
  {
    const std::string file = temporary_archive();
    {
      coupling::Hdf5ArchiveWriter writer(file, {"test", ""});
      coupling::save_bed(writer, "state", bed);
      writer.commit();
    }
    const coupling::Hdf5ArchiveReader reader(file);
    dem::Bed restored = coupling::load_bed(reader, "state", model);
    std::filesystem::remove(file);
    return restored;
  }

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

  dem::Bed restored = restart(original, model);

  ASSERT_EQ(restored.particles.size(), original.particles.size());
  for (std::size_t i = 0; i < original.particles.size(); ++i)
    EXPECT_EQ(restored.particles.positions[i], original.particles.positions[i]);
  std::size_t with_history = 0;
  double      sum_a_p = 0, restored_sum_a_p = 0;
  for (const auto &c : original.contacts.pairs)
    {
      with_history += dem::BondedElastoplasticLaw::a_p(c.history) > 0;
      sum_a_p += dem::BondedElastoplasticLaw::a_p(c.history);
    }
  for (const auto &c : restored.contacts.pairs)
    restored_sum_a_p += dem::BondedElastoplasticLaw::a_p(c.history);
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

/// The largest overlaps delta_max of a hysteretic law (Walton-Braun) are
/// internal variables too: every contact of the restored bed has the
/// history it was saved with, all three variables bit for bit.
TEST(BedCheckpoint, LargestOverlapsOfAHystereticLawSurvive)
{
  const dem::ContactModel model = compax::testing::walton_braun_model();
  dem::LoadStepper        stepper(model);
  const dem::Bed          original = compacted_bed(stepper);
  const dem::Bed          restored = restart(original, model);

  // Active or dormant: the restart sets aside the pairs that are far apart
  // at the saved positions.
  std::map<std::pair<std::uint32_t, std::uint32_t>, dem::ContactHistory> saved;
  original.contacts.for_each_kept_pair([&](const dem::PairContact &c) {
    if (dem::has_history(c.history))
      saved[{c.i, c.j}] = c.history;
  });
  ASSERT_GT(saved.size(), 10u);
  std::size_t found = 0;
  restored.contacts.for_each_kept_pair([&](const dem::PairContact &c) {
    const auto s = saved.find({c.i, c.j});
    if (s == saved.end())
      {
        EXPECT_FALSE(dem::has_history(c.history));
        return;
      }
    EXPECT_EQ(c.history, s->second);
    ++found;
  });
  EXPECT_EQ(found, saved.size());
}

/// A pair set aside as dormant (parted beyond the skin plus its reach) is
/// saved with its history and set aside again on restart; the pair that
/// touches stays active.
TEST(BedCheckpoint, DormantPairsSurvive)
{
  const dem::ContactModel model = compax::testing::material1::contact_model();
  const double            R     = compax::testing::material1::R;
  dem::Bed                bed;
  bed.walls.diameter    = 40 * R;
  bed.walls.lower_punch = 0.0;
  bed.walls.upper_punch = 10 * R;
  bed.particles.add({0.0, 0.0, 5 * R}, R);
  bed.particles.add({2 * R - 1e-6, 0.0, 5 * R}, R);
  bed.particles.add({-2 * R + 1e-6, 0.0, 5 * R}, R);
  bed.contacts = dem::ContactSet(0.3 * R);
  bed.contacts.rebuild(bed.particles, bed.walls, model);
  ASSERT_EQ(bed.contacts.pairs.size(), 2u);
  const auto  &law = dem::bonded_law(bed.contacts.pairs[0].law);
  const double a_p = law.plastic_radius(1e-6);
  for (auto &c : bed.contacts.pairs)
    c.history = dem::BondedElastoplasticLaw::history(a_p, a_p);
  bed.particles.positions[2] = {-4 * R, 0.0, 5 * R};
  bed.contacts.rebuild(bed.particles, bed.walls, model);
  ASSERT_EQ(bed.contacts.dormant.size(), 1u);

  const dem::Bed restored = restart(bed, model);
  ASSERT_EQ(restored.contacts.pairs.size(), 1u);
  ASSERT_EQ(restored.contacts.dormant.size(), 1u);
  EXPECT_EQ(restored.contacts.pairs[0].j, 1u);
  EXPECT_EQ(restored.contacts.dormant[0].j, 2u);
  EXPECT_EQ(restored.contacts.dormant[0].history,
            dem::BondedElastoplasticLaw::history(a_p, a_p));
}

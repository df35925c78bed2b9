// Force-network statistics and the ParaView snapshot of a hand-built bed: a
// vertical column of three overlapping spheres, whose contact forces follow
// from the contact law at the known overlaps.

#include "dem/analysis/bed_statistics.h"
#include "dem/io/particle_vtu.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/vtu_text.h"

#include <gtest/gtest.h>

#include <unistd.h>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

namespace
{
  using material1::R;
  constexpr double overlap = 2e-6;

  Bed
  column_of_three(const ContactModel &model)
  {
    Bed bed;
    for (int k = 0; k < 3; ++k)
      bed.particles.add({0, 0, R + k * (2 * R - overlap)}, R);
    bed.walls.diameter    = 20 * R;
    bed.walls.lower_punch = 0.0;
    bed.walls.upper_punch = 10 * R;
    bed.contacts.set_skin(0.3 * R);
    bed.contacts.rebuild(bed.particles, bed.walls, model);
    return bed;
  }
} // namespace

TEST(BedStatistics, LoadedContactsOfAColumnFollowTheLaw)
{
  const auto model   = material1::contact_model();
  const Bed  bed     = column_of_three(model);
  const auto network = loaded_contacts(bed);
  ASSERT_EQ(network.forces.size(), 2u);
  const auto   law = bonded_law(model.pair_law(0, R, 0, R));
  const double P   = law.response(overlap, 0, 0).force;
  for (std::size_t c = 0; c < 2; ++c)
    {
      EXPECT_NEAR(network.forces[c], P, 1e-9 * P);
      EXPECT_NEAR(std::abs(network.normals[c][2]), 1.0, 1e-12);
    }
}

TEST(BedStatistics, HistogramCountsEveryForceOnce)
{
  const std::vector<double> forces{-2, -1, 0.5, 1, 1, 3, 4};
  const auto                h = force_histogram(forces, 3);
  EXPECT_EQ(h.counts, (std::vector<std::size_t>{2, 3, 2}));
  EXPECT_DOUBLE_EQ(h.centres[0], -2 + 1.0);
}

TEST(ParticleVtu, SnapshotHasEveryParticleAndItsCoordination)
{
  const auto model = material1::contact_model();
  const Bed  bed   = column_of_three(model);
  const auto file  = std::filesystem::temp_directory_path()
                    / ("compax-vtu-" + std::to_string(::getpid()) + ".vtu");
  write_particles_vtu(file, bed);
  const compax::testing::VtuText vtu(file);
  std::filesystem::remove(file);
  EXPECT_NE(vtu.text.find("NumberOfPoints=\"3\""), std::string::npos);
  // The middle sphere touches two, the ends one each.
  EXPECT_EQ(vtu.array("coordination", 3), (std::vector<double>{1, 2, 1}));
}

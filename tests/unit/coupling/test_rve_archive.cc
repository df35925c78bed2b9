// HDF5 checkpoints of an RVE state: every field survives the round trip
// exactly, and one more strain step from the restored state equals the
// step of the original (the restart is faithful), the property `compax rve
// --Resume from` rests on.

#include "coupling/rve_archive.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"

#include "tests/support/gonzalez_material1.h"
#include "tests/support/narrow_polydisperse_cell.h"
#include "tests/support/temporary_folder.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

using namespace compax;
namespace fs = std::filesystem;

namespace
{
  namespace material1 = compax::testing::material1;
  using material1::R;

  class RveArchive : public compax::testing::TemporaryFolderTest
  {
  };

  /// A bonded, plastically loaded cell: 80 spheres of Material 1 compacted
  /// in uniaxial strain to a relative density of 0.74 (plastic histories,
  /// bonds, a deformed lattice).
  dem::PeriodicBed
  loaded_cell(const dem::ContactModel &model)
  {
    dem::PeriodicBed bed = dem::make_periodic_packing(
      compax::testing::narrow_polydisperse_cell(80, R, 1.25, 0.58, 5), model);
    dem::RveLoading loading(model);
    const double    rho0 = bed.relative_density();
    for (const double rho : {0.64, 0.68, 0.71, 0.74})
      {
        Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
        F(2, 2)           = rho0 / rho;
        EXPECT_TRUE(loading.deform_to(bed, F).converged);
      }
    return bed;
  }

  /// A strain increment with every component, so the step exercises the
  /// whole lattice.
  Eigen::Matrix3d
  mixed_increment()
  {
    Eigen::Matrix3d e;
    e << -2e-3, 3e-4, -2e-4, //
      3e-4, -1e-3, 1e-4,     //
      -2e-4, 1e-4, -6e-3;
    return e;
  }
} // namespace

TEST_F(RveArchive, RoundTripKeepsEveryField)
{
  const dem::ContactModel model = material1::contact_model();
  const dem::PeriodicBed  bed   = loaded_cell(model);
  const std::string       file  = (dir / "rve.h5").string();
  coupling::save_rve(file, bed);
  const dem::PeriodicBed back = coupling::load_rve(file, model);

  ASSERT_EQ(back.particles.size(), bed.particles.size());
  for (std::size_t i = 0; i < bed.particles.size(); ++i)
    {
      EXPECT_EQ(back.particles.positions[i], bed.particles.positions[i]);
      EXPECT_EQ(back.particles.radii[i], bed.particles.radii[i]);
      EXPECT_EQ(back.particles.materials[i], bed.particles.materials[i]);
    }
  EXPECT_EQ(back.cell.lattice(), bed.cell.lattice());
  EXPECT_EQ(back.reference_lattice, bed.reference_lattice);
  EXPECT_EQ(back.deformation, bed.deformation);
  EXPECT_EQ(back.contacts.skin(), bed.contacts.skin());

  // Every contact with a history is back with the same history; the
  // plastic state is not trivial.
  std::size_t with_history = 0, bonded = 0;
  for (const dem::PeriodicContact &c : bed.contacts.pairs)
    {
      if (c.history == dem::ContactHistory{})
        continue;
      ++with_history;
      bonded += dem::BondedElastoplasticLaw::a_B(c.history) > 0.0;
      bool found = false;
      for (const dem::PeriodicContact &d : back.contacts.pairs)
        if (d.i == c.i && d.j == c.j && d.image == c.image)
          {
            EXPECT_EQ(d.history, c.history);
            found = true;
          }
      EXPECT_TRUE(found) << c.i << "-" << c.j;
    }
  EXPECT_GT(with_history, bed.particles.size());
  EXPECT_GT(bonded, 0u);

  // The Love-Weber stress sums the same contacts in the same order.
  EXPECT_EQ(dem::love_weber_stress(back), dem::love_weber_stress(bed));
}

TEST_F(RveArchive, OneMoreStepFromTheRestoredStateEqualsTheOriginal)
{
  const dem::ContactModel model    = material1::contact_model();
  dem::PeriodicBed        original = loaded_cell(model);
  const std::string       file     = (dir / "rve.h5").string();
  coupling::save_rve(file, original);
  // A checkpointing run refreshes its Verlet list at the checkpoint (as the
  // restored cell does when it is loaded) and starts a fresh driver.
  original.contacts.rebuild(original.particles, original.cell, model);
  dem::PeriodicBed restored = coupling::load_rve(file, model);

  dem::RveLoading a(model), b(model);
  const auto      ra = a.apply_strain(original, mixed_increment());
  const auto      rb = b.apply_strain(restored, mixed_increment());
  ASSERT_TRUE(ra.converged);
  ASSERT_TRUE(rb.converged);
  EXPECT_EQ(ra.iterations, rb.iterations);

  for (std::size_t i = 0; i < original.particles.size(); ++i)
    EXPECT_LT((restored.particles.positions[i]
               - original.particles.positions[i])
                .norm(),
              1e-9 * R)
      << "particle " << i;
  const Eigen::Matrix3d sa = dem::love_weber_stress(original);
  const Eigen::Matrix3d sb = dem::love_weber_stress(restored);
  EXPECT_LT((sa - sb).norm(), 1e-9 * sa.norm());
  // Internal variables after the step's history update.
  ASSERT_EQ(original.contacts.pairs.size(), restored.contacts.pairs.size());
  for (std::size_t k = 0; k < original.contacts.pairs.size(); ++k)
    {
      const auto &c = original.contacts.pairs[k];
      const auto &d = restored.contacts.pairs[k];
      EXPECT_EQ(c.i, d.i);
      EXPECT_EQ(c.j, d.j);
      EXPECT_NEAR(dem::BondedElastoplasticLaw::a_p(c.history),
                  dem::BondedElastoplasticLaw::a_p(d.history),
                  1e-9 * R);
      EXPECT_NEAR(dem::BondedElastoplasticLaw::a_B(c.history),
                  dem::BondedElastoplasticLaw::a_B(d.history),
                  1e-9 * R);
    }
}

TEST_F(RveArchive, NotAnRveArchiveIsRejected)
{
  const dem::ContactModel model = material1::contact_model();
  const std::string       file  = (dir / "other.h5").string();
  {
    coupling::Hdf5ArchiveWriter w(file, {"something-else", ""});
    w.commit();
  }
  EXPECT_THROW(coupling::load_rve(file, model), coupling::Hdf5ArchiveError);
  EXPECT_THROW(coupling::load_rve((dir / "missing.h5").string(), model),
               coupling::Hdf5ArchiveError);
}

// Checkpoint of the FE2 material (RveMaterial::save_state/load_state): a
// fresh material with the saved histories and the loaded RVEs continues
// exactly as the saved one does (exact restart = uninterrupted run), also
// from the state right after a commit, whose newest cell is still the
// (rotated) trial cell; and a checkpoint of other points or another pool
// is refused.
#include "coupling/rve_material.h"
#include "fe2_test_support.h"

#include <deal.II/base/tensor.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

using namespace compax;

namespace
{
  constexpr double R = 100e-6;

  namespace material1 = compax::testing::material1;

  /// A pool of one simple cubic lattice at spacing a.
  coupling::RveMaterialSpec
  lattice_spec(const double a)
  {
    coupling::RveMaterialSpec spec;
    spec.pool
      = {compax::testing::simple_cubic_cell(a, R, material1::contact_model())};
    spec.compaction_axis                     = 2;
    spec.tangent_floor_modulus               = 1e3;
    spec.loading.equilibrium.force_tolerance = 1e-10;
    return spec;
  }

  constexpr double spacing = 2 * R - 0.01 * R;

  /// Axial compression with a lateral strain (the lattice's affine map is
  /// its equilibrium for any such stretch).
  fem::MaterialIncrement
  increment(const double eps_zz, const double eps_xx)
  {
    fem::MaterialIncrement inc;
    inc.strain_increment[2][2]      = eps_zz;
    inc.strain_increment[0][0]      = eps_xx;
    inc.deformation_increment[2][2] = 1.0 + eps_zz;
    inc.deformation_increment[0][0] = 1.0 + eps_xx;
    return inc;
  }

  /// Rotation by @p angle about z.
  dealii::Tensor<2, 3>
  rotation(const double angle)
  {
    dealii::Tensor<2, 3> Q;
    Q[0][0] = Q[1][1] = std::cos(angle);
    Q[0][1]           = -std::sin(angle);
    Q[1][0]           = std::sin(angle);
    Q[2][2]           = 1.0;
    return Q;
  }

  using Histories = std::vector<std::vector<double>>;

  /// Points at these initial densities: the lattice's own (jams in the
  /// first step) and looser ones that stay unjammed (no cell).
  Histories
  initialize(const coupling::RveMaterial &m, const std::vector<double> &rho)
  {
    Histories h(rho.size(), std::vector<double>(m.n_history()));
    for (std::size_t p = 0; p < rho.size(); ++p)
      m.initialize(rho[p], h[p]);
    return h;
  }

  /// One converged step of every point as the solver does it: evaluate,
  /// copy the trial history over the committed one, rotate at commit.
  std::vector<fem::MaterialResponse>
  step(const coupling::RveMaterial  &m,
       Histories                    &h,
       const fem::MaterialIncrement &inc,
       const dealii::Tensor<2, 3>   &Q)
  {
    std::vector<fem::MaterialResponse> responses(h.size());
    std::vector<double>                trial(m.n_history());
    for (std::size_t p = 0; p < h.size(); ++p)
      {
        EXPECT_TRUE(m.evaluate(inc, h[p], trial, responses[p]));
        h[p] = trial;
        m.rotate(h[p], Q);
      }
    return responses;
  }

  class RveMaterialCheckpoint : public ::testing::Test
  {
  protected:
    void
    SetUp() override
    {
      folder
        = std::filesystem::temp_directory_path()
          / ("compax-rve-material-checkpoint-" + std::to_string(::getpid()));
      std::filesystem::remove_all(folder);
      std::filesystem::create_directories(folder);
    }

    void
    TearDown() override
    {
      std::filesystem::remove_all(folder);
    }

    std::filesystem::path folder;
  };

  const std::vector<double> densities
    = {4.0 / 3.0 * M_PI * R * R * R / (spacing * spacing * spacing),
       0.3,
       4.0 / 3.0 * M_PI *R *R *R / (spacing * spacing * spacing)};
} // namespace

TEST_F(RveMaterialCheckpoint, LoadedMaterialContinuesAsTheSavedOne)
{
  const dem::ContactModel model = material1::contact_model();
  coupling::RveMaterial   original(lattice_spec(spacing), model);
  Histories               h = initialize(original, densities);
  // Two committed steps (the first switches the dense points to their
  // lattice), each rotating the cells at commit; checkpoint right after
  // the second commit, when the newest cells are still the trial cells.
  step(original, h, increment(-1e-3, 2e-4), rotation(0.01));
  step(original, h, increment(-1e-3, -1e-4), rotation(-0.02));
  ASSERT_TRUE(coupling::RveMaterial::is_jammed(h[0]));
  ASSERT_FALSE(coupling::RveMaterial::is_jammed(h[1]));
  original.save_state(folder, 0);
  EXPECT_TRUE(std::filesystem::is_regular_file(folder / "rve.0.h5"));
  EXPECT_FALSE(std::filesystem::exists(folder / "rve.0.h5.tmp"));

  // A fresh material as a resumed solver builds it: points initialized as
  // at the start, histories read back, then the RVEs.
  coupling::RveMaterial resumed(lattice_spec(spacing), model);
  Histories             g = initialize(resumed, densities);
  g                       = h;
  resumed.load_state(folder, 0);

  // Loading, then compaction, then an unloading step: every response and
  // history of both equal (the lattice stays affine, so the equilibria are
  // the predictors and agree to round-off).
  const fem::MaterialIncrement path[]
    = {increment(-1e-3, 1e-4), increment(-2e-3, 0.0), increment(5e-4, -1e-4)};
  for (std::size_t k = 0; k < 3; ++k)
    {
      const auto a = step(original, h, path[k], rotation(0.01 * k));
      const auto b = step(resumed, g, path[k], rotation(0.01 * k));
      // The dense points carry their lattice's contact stress in
      // compaction (~1 MPa, the floor's ~1 Pa): the comparison is not one
      // of empty cells.
      if (k < 2)
        {
          EXPECT_LT(a[0].stress[2][2], -1e5);
        }
      for (std::size_t p = 0; p < h.size(); ++p)
        {
          EXPECT_LE((a[p].stress - b[p].stress).norm(),
                    1e-12 * a[p].stress.norm())
            << "step " << k << " point " << p;
          EXPECT_LE((a[p].tangent - b[p].tangent).norm(),
                    1e-12 * a[p].tangent.norm())
            << "step " << k << " point " << p;
          for (unsigned int i = 0; i < original.n_history(); ++i)
            EXPECT_NEAR(h[p][i], g[p][i], 1e-12 * std::abs(h[p][i]))
              << "step " << k << " point " << p << " entry " << i;
        }
    }
  // The committed cells (promoted from the trials of the last step but
  // one) hold the same particles and lattice.
  for (std::size_t p = 0; p < h.size(); ++p)
    {
      const dem::PeriodicBed &x = original.committed_cell(p),
                             &y = resumed.committed_cell(p);
      ASSERT_EQ(x.particles.size(), y.particles.size()) << p;
      EXPECT_LE((x.cell.lattice() - y.cell.lattice()).norm(),
                1e-15 * x.cell.lattice().norm());
      for (std::size_t i = 0; i < x.particles.size(); ++i)
        EXPECT_LE((x.particles.positions[i] - y.particles.positions[i]).norm(),
                  1e-15 * spacing);
    }
}

TEST_F(RveMaterialCheckpoint, CheckpointOfOtherPointsOrPoolIsRefused)
{
  const dem::ContactModel model = material1::contact_model();
  coupling::RveMaterial   saved(lattice_spec(spacing), model);
  Histories               h = initialize(saved, densities);
  step(saved, h, increment(-1e-3, 0.0), rotation(0.0));
  saved.save_state(folder, 0);

  const auto message
    = [&](const coupling::RveMaterial &m, const unsigned int rank) {
        try
          {
            m.load_state(folder, rank);
          }
        catch (const std::runtime_error &e)
          {
            return std::string(e.what());
          }
        return std::string("no error");
      };
  // Another number of points (another mesh or partition).
  coupling::RveMaterial fewer(lattice_spec(spacing), model);
  initialize(fewer, {densities[0], densities[1]});
  EXPECT_NE(message(fewer, 0).find("3 material points, this run has 2"),
            std::string::npos)
    << message(fewer, 0);
  // Another pool (other Multiscale parameters).
  coupling::RveMaterial other(lattice_spec(0.999 * spacing), model);
  initialize(other, densities);
  EXPECT_NE(message(other, 0).find("RVE pool differs"), std::string::npos)
    << message(other, 0);
  // No file of this rank (a checkpoint of a run without RVEs).
  coupling::RveMaterial same(lattice_spec(spacing), model);
  initialize(same, densities);
  EXPECT_NE(message(same, 1).find("rve.1.h5: missing"), std::string::npos)
    << message(same, 1);
  // A failed load leaves the material as it was: it still loads the right
  // file afterwards.
  EXPECT_EQ(message(same, 0), "no error");
}

/// A drawn 60-particle packing jammed by uniaxial compaction: its
/// equilibria are Newton solves with contacts opening and closing, and the
/// resumed point still repeats every step (the checkpoint refreshes the
/// running cells' contact lists as loading does).
TEST_F(RveMaterialCheckpoint, DrawnPackingContinuesAsTheSavedOne)
{
  const coupling::RveMaterialSpec spec  = compax::testing::small_drawn_spec();
  const dem::ContactModel         model = material1::contact_model();
  coupling::RveMaterial           original(spec, model);
  Histories                       h = initialize(original, {0.6});
  for (int k = 0; k < 20; ++k)
    step(original, h, increment(-0.01, 0.0), rotation(0.0));
  ASSERT_TRUE(coupling::RveMaterial::is_jammed(h[0]));
  original.save_state(folder, 0);

  coupling::RveMaterial resumed(spec, model);
  Histories             g = initialize(resumed, {0.6});
  g                       = h;
  resumed.load_state(folder, 0);
  // Further compaction with a lateral stretch, then unloading.
  for (const double eps_zz : {-0.005, -0.005, -0.005, 0.002, 0.002})
    {
      const auto a = step(original, h, increment(eps_zz, 0.001), rotation(0.0));
      const auto b = step(resumed, g, increment(eps_zz, 0.001), rotation(0.0));
      EXPECT_LE((a[0].stress - b[0].stress).norm(), 1e-12 * a[0].stress.norm())
        << eps_zz;
      EXPECT_LE((a[0].tangent - b[0].tangent).norm(),
                1e-12 * a[0].tangent.norm())
        << eps_zz;
      // In compaction, a jammed RVE's tangent (~1 GPa), not the floor's
      // (1 MPa): the comparison is not one of floors.
      if (eps_zz < 0.0)
        {
          EXPECT_GT(a[0].tangent.norm(), 1e8);
        }
    }
}

// The tablet study as a library class: an elastic compact against uniaxial
// strain, the summary against its history, and a resumed study against
// the uninterrupted one.
#include "../../support/temporary_folder.h"
#include "../fem/mcc_tablet.h"
#include "coupling/tablet_checkpoint.h"
#include "coupling/tablet_study.h"
#include "fem/isotropic_elasticity.h"
#include "fem/linear_elastic_material.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

namespace coupling = compax::coupling;
namespace fem      = compax::fem;

namespace
{
  std::string
  bytes(const std::filesystem::path &file)
  {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }

  /// The largest upper punch pressure of the compaction steps [Pa].
  double
  max_compaction_pressure(const coupling::TabletStudyResult &r)
  {
    double p = 0.0;
    for (const auto &st : r.history)
      if (st.stage == fem::TabletStage::compaction)
        p = std::max(p, st.forces.upper_punch_force / r.punch_area);
    return p;
  }

  /// The DPC cycle of the solver's checkpoint test (20 + 5 + 6 steps).
  std::unique_ptr<coupling::TabletStudy<2>>
  short_study(const coupling::TabletStudyOptions &options)
  {
    return std::make_unique<coupling::TabletStudy<2>>(
      compax::testing::mcc_tablet_settings(),
      compax::testing::mcc_short_cycle(),
      compax::testing::mcc_material(),
      options,
      MPI_COMM_SELF);
  }

  class TabletStudyFiles : public compax::testing::TemporaryFolderTest
  {
  };
} // namespace

TEST(TabletStudy, ElasticCompactInAFrictionlessDieIsInUniaxialStrain)
{
  constexpr double          E = 2e9, nu = 0.3;
  fem::TabletSolverSettings s;
  s.geometry.die_diameter    = 10e-3;
  s.geometry.fill_height     = 5e-3;
  s.geometry.n_radial_cells  = 4;
  s.wall_friction            = 0.0;
  s.initial_relative_density = 0.8;
  // Punch and wall penetrations negligible against the tolerance.
  s.penalty_factor = 1e7;
  s.tolerance      = 1e-9;
  fem::TabletProcess process;
  process.compaction_displacement = 1e-4 * s.geometry.fill_height;
  process.compaction_steps        = 2;
  process.unloading_steps         = 0;
  process.ejection_steps          = 0;

  // No folder: the result in memory only.
  coupling::TabletStudy<2> study(
    s,
    process,
    std::make_shared<fem::LinearElasticMaterial>(E, nu),
    {},
    MPI_COMM_SELF);
  std::vector<coupling::TabletProgress> progress;
  study.on_step
    = [&](const coupling::TabletProgress &p) { progress.push_back(p); };
  const coupling::TabletStudyResult r = study.run();
  ASSERT_TRUE(r.converged);
  ASSERT_EQ(r.history.size(), 3u);
  ASSERT_EQ(progress.size(), 3u);
  EXPECT_FALSE(r.fe2);
  EXPECT_EQ(r.resumed_after, 0u);

  const double lambda = fem::lame_lambda(E, nu), mu = fem::shear_modulus(E, nu);
  for (unsigned int k = 1; k < 3; ++k)
    {
      const auto  &st  = r.history[k];
      const double eps = st.upper_punch_displacement / s.geometry.fill_height;
      EXPECT_NEAR(eps, 0.5e-4 * k, 1e-15);
      // The small-strain closed form, to terms of the order of the strain
      // (the model is geometrically nonlinear).
      EXPECT_NEAR(st.forces.upper_punch_force / r.punch_area
                    / ((lambda + 2 * mu) * eps),
                  1.0,
                  eps)
        << "step " << k;
      EXPECT_NEAR(coupling::die_wall_pressure(st.forces) / (lambda * eps),
                  1.0,
                  eps)
        << "step " << k;
      EXPECT_EQ(progress[k].step.index, k);
      EXPECT_EQ(progress[k].n_steps, 2u);
      EXPECT_EQ(progress[k].upper_punch_pressure,
                st.forces.upper_punch_force / r.punch_area);
    }
  EXPECT_EQ(r.summary.max_upper_pressure, max_compaction_pressure(r));
  EXPECT_EQ(r.summary.density_at_max, r.history[2].mean_relative_density);
}

TEST_F(TabletStudyFiles, ResumedStudyEqualsTheUninterruptedOne)
{
  coupling::TabletStudyOptions options;
  options.folder              = dir / "full";
  options.field_interval      = 5;
  options.checkpoint_interval = 7;
  options.parameters          = "short DPC cycle";
  std::filesystem::create_directories(options.folder);
  const coupling::TabletStudyResult a = short_study(options)->run();
  ASSERT_TRUE(a.converged);
  ASSERT_EQ(a.history.size(), 32u);
  EXPECT_EQ(a.summary.max_upper_pressure, max_compaction_pressure(a));
  EXPECT_GT(a.summary.max_upper_pressure, 50e6);
  EXPECT_GT(a.summary.peak_ejection_force, 0.0);

  // Its last checkpoint, of step 28 (ejection), continued elsewhere.
  options.folder      = dir / "resumed";
  options.resume_from = dir / "full";
  std::filesystem::create_directories(options.folder);
  const auto   resumed       = short_study(options);
  unsigned int resumed_after = 0, steps_run = 0;
  resumed->on_resume
    = [&](const fem::TabletStep &st) { resumed_after = st.index; };
  resumed->on_step = [&](const coupling::TabletProgress &) { ++steps_run; };
  const coupling::TabletStudyResult b = resumed->run();
  ASSERT_TRUE(b.converged);
  EXPECT_EQ(resumed_after, 28u);
  EXPECT_EQ(b.resumed_after, 28u);
  EXPECT_EQ(steps_run, 3u);

  // The restored state retraces the same Newton path: equal to the bit.
  ASSERT_EQ(b.history.size(), a.history.size());
  for (std::size_t k = 0; k < a.history.size(); ++k)
    {
      const auto &x = a.history[k], &y = b.history[k];
      EXPECT_EQ(x.stage, y.stage) << "step " << k;
      EXPECT_EQ(x.time, y.time) << "step " << k;
      EXPECT_EQ(x.forces.upper_punch_force, y.forces.upper_punch_force)
        << "step " << k;
      EXPECT_EQ(x.forces.lower_punch_force, y.forces.lower_punch_force)
        << "step " << k;
      EXPECT_EQ(x.forces.die_wall_normal_force, y.forces.die_wall_normal_force)
        << "step " << k;
      EXPECT_EQ(x.mean_relative_density, y.mean_relative_density)
        << "step " << k;
      EXPECT_EQ(x.mean_stress, y.mean_stress) << "step " << k;
    }
  EXPECT_EQ(b.summary.peak_ejection_force, a.summary.peak_ejection_force);
  EXPECT_EQ(b.summary.mean_stress_out_of_die, a.summary.mean_stress_out_of_die);
  EXPECT_EQ(bytes(dir / "resumed" / "tablet.csv"),
            bytes(dir / "full" / "tablet.csv"));
  // The field outputs up to the checkpoint are copied over.
  EXPECT_TRUE(std::filesystem::exists(dir / "resumed" / "tablet_0025.pvtu"));
  EXPECT_TRUE(std::filesystem::exists(dir / "resumed" / "tablet_0031.pvtu"));
}

TEST_F(TabletStudyFiles, UnusableCheckpointsAreRefusedWithTheReason)
{
  coupling::TabletStudyOptions options;
  options.folder      = dir / "out";
  options.resume_from = dir / "nowhere";
  std::filesystem::create_directories(options.folder);
  const auto reason = [&] {
    try
      {
        short_study(options)->run();
      }
    catch (const coupling::TabletResumeError &e)
      {
        return std::string(e.what());
      }
    return std::string();
  };
  EXPECT_EQ(reason(), "no such folder");
  options.resume_from = dir / "out";
  EXPECT_EQ(reason(),
            "has no checkpoint folder (run with Checkpoint "
            "interval > 0)");
}

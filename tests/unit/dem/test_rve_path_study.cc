// The RVE strain-path study of the library (dem::RvePathStudy) on a small
// cell, without the app: the uniaxial path against its closed form, the
// condensed tangent against central finite differences and below the
// affine (Voigt) tangent, a stopped and resumed study equal to the
// uninterrupted one bit for bit, and the spread of a size study.

#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_path_study.h"
#include "dem/rve/rve_size_study.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/narrow_polydisperse_cell.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

namespace
{
  PeriodicBed
  small_cell(const ContactModel &model)
  {
    return make_periodic_packing(
      compax::testing::narrow_polydisperse_cell(60, material1::R, 1.2, 0.60, 7),
      model);
  }

  /// Uniaxial compaction to 0.72 in 6 steps, unloading in strain steps of
  /// 3e-3, tangents every step.
  RvePathStudyOptions
  uniaxial_options()
  {
    RvePathStudyOptions o;
    o.path             = RveStrainPath::uniaxial;
    o.target_density   = 0.72;
    o.steps            = 6;
    o.unloading_step   = 3e-3;
    o.tangent_interval = 1;
    return o;
  }
} // namespace

/// The cell follows the uniaxial path exactly (eps_xx = eps_yy = 0, mass
/// conservation eps_zz = ln(rho_0 / rho), equal density steps), jams, and
/// unloads until the axial stress vanishes. Its condensed tangent agrees
/// with central differences of the stress, and the affine tangent is an
/// upper (Voigt) bound of it: relaxing the fluctuations can only lower the
/// stiffness, sym(C_affine - C_condensed) = G^T K^-1 G / V >= 0.
TEST(RvePathStudy, UniaxialPathTangentsAndBounds)
{
  const ContactModel  model = material1::contact_model();
  RvePathStudyOptions o     = uniaxial_options();
  o.fd_interval             = 3;
  RvePathStudy    study(model, o, RvePathState{small_cell(model)});
  const double    rho0        = study.state().bed.relative_density();
  int             step_events = 0, initial_events = 0;
  RvePathObserver observer;
  observer.step = [&](const RvePathStepEvent &) { ++step_events; };
  observer.state
    = [&](const RvePathStateEvent &e) { initial_events += e.initial; };
  const RvePathResult r = study.run(observer);
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_FALSE(r.stopped);
  EXPECT_EQ(initial_events, 1);
  EXPECT_EQ(step_events, int(r.steps.size()) - 1);

  int loading = 0;
  for (const RvePathStep &s : r.steps)
    {
      EXPECT_EQ(s.strain(0, 0), 0.0) << "step " << s.step;
      EXPECT_EQ(s.strain(1, 1), 0.0) << "step " << s.step;
      EXPECT_NEAR(s.strain(2, 2), std::log(rho0 / s.relative_density), 1e-12)
        << "step " << s.step;
      if (!s.unloading && s.step > 0)
        {
          EXPECT_NEAR(s.relative_density,
                      rho0 + (0.72 - rho0) * s.step / o.steps,
                      1e-12);
        }
      loading += !s.unloading && s.step > 0;
    }
  EXPECT_EQ(loading, o.steps);
  ASSERT_TRUE(r.steps.back().unloading);
  EXPECT_GE(r.steps.back().stress(2, 2), 0.0);
  EXPECT_LT(r.steps[o.steps].stress(2, 2), -1e6);

  int checked = 0;
  ASSERT_FALSE(r.moduli.empty());
  for (const RvePathModuli &m : r.moduli)
    {
      const Matrix6d C = m.current.condensed, A = m.current.affine;
      const Matrix6d D = 0.5 * ((A - C) + (A - C).transpose());
      const double   min_eigenvalue
        = Eigen::SelfAdjointEigenSolver<Matrix6d>(D).eigenvalues().minCoeff();
      EXPECT_GE(min_eigenvalue, -1e-6 * A.norm()) << "step " << m.step;
      EXPECT_LE(m.condensed_projection(2, 2), m.affine_projection(2, 2));
      EXPECT_GT(m.isotropic.youngs_modulus, 0.0);
      if (!std::isnan(m.fd_error))
        {
          EXPECT_LT(m.fd_error, 1e-4) << "step " << m.step;
          ++checked;
        }
    }
  EXPECT_GT(checked, 0);
}

/// A study stopped after step 4 and resumed from its state gives the
/// uninterrupted study's states and tangents bit for bit: every step
/// starts afresh from the state a checkpoint holds.
TEST(RvePathStudy, StoppedAndResumedEqualsUninterrupted)
{
  const ContactModel        model = material1::contact_model();
  const RvePathStudyOptions o     = uniaxial_options();
  RvePathStudy        whole_study(model, o, RvePathState{small_cell(model)});
  const RvePathResult whole = whole_study.run();
  ASSERT_TRUE(whole.converged) << whole.failure;

  RvePathStudyOptions first_options = o;
  first_options.stop_after          = 4;
  RvePathStudy        first_study(model,
                           first_options,
                           RvePathState{small_cell(model)});
  const RvePathResult first = first_study.run();
  ASSERT_TRUE(first.stopped);
  ASSERT_EQ(first.steps.size(), 5u);
  RvePathStudy        second_study(model, o, first_study.state());
  const RvePathResult second = second_study.run();
  ASSERT_TRUE(second.converged) << second.failure;

  std::vector<RvePathStep> steps = first.steps;
  steps.insert(steps.end(), second.steps.begin(), second.steps.end());
  std::vector<RvePathModuli> moduli = first.moduli;
  moduli.insert(moduli.end(), second.moduli.begin(), second.moduli.end());
  ASSERT_EQ(steps.size(), whole.steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k)
    {
      EXPECT_EQ(steps[k].step, whole.steps[k].step);
      EXPECT_EQ(steps[k].unloading, whole.steps[k].unloading);
      EXPECT_EQ(steps[k].strain, whole.steps[k].strain) << "step " << k;
      EXPECT_EQ(steps[k].stress, whole.steps[k].stress) << "step " << k;
      EXPECT_EQ(steps[k].measures.coordination_number,
                whole.steps[k].measures.coordination_number);
    }
  ASSERT_EQ(moduli.size(), whole.moduli.size());
  for (std::size_t k = 0; k < moduli.size(); ++k)
    {
      EXPECT_EQ(moduli[k].current.condensed, whole.moduli[k].current.condensed)
        << "step " << moduli[k].step;
      EXPECT_EQ(moduli[k].unloading_condensed,
                whole.moduli[k].unloading_condensed);
    }
}

/// The spread between cell sizes leaves out missing values.
TEST(RveSizeStudy, SpreadLeavesOutMissingValues)
{
  const double  nan = std::numeric_limits<double>::quiet_NaN();
  RveSizeSpread s   = size_spread("E", {2.0, nan, 6.0});
  EXPECT_EQ(s.count, 2);
  EXPECT_EQ(s.min, 2.0);
  EXPECT_EQ(s.max, 6.0);
  EXPECT_EQ(s.mean, 4.0);
  EXPECT_EQ(s.spread, 1.0);
  s = size_spread("E", {nan});
  EXPECT_EQ(s.count, 0);
  EXPECT_TRUE(std::isnan(s.spread));
}

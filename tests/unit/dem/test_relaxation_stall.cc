#include "dem/solver/fire_relaxation.h"
#include "dem/solver/lbfgs_relaxation.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/sphere_column.h"

#include <gtest/gtest.h>

#include <vector>

using namespace compax::dem;

namespace
{
  using compax::testing::material1::R;

  /**
   * A sphere on an endless slope: a constant force f along x and a
   * stiffness k that holds nothing (the energy is linear in x), so no
   * state is balanced. The "mean contact force" is f, so the distance to
   * balance, f over target f, never changes.
   */
  class EndlessSlope : public EquilibriumSystem
  {
  public:
    static constexpr double f = 1.0e-3; // [N]
    static constexpr double k = 1.0e5;  // [N/m]

    std::size_t
    n_particles() const override
    {
      return 1;
    }
    double
    mean_radius() const override
    {
      return R;
    }
    double
    skin() const override
    {
      return 0.1 * R;
    }
    Eigen::Map<Eigen::VectorXd>
    coordinates() override
    {
      return {x.data(), 3};
    }
    ContactSums
    residual(Eigen::VectorXd &F) override
    {
      ++evaluations;
      F = Eigen::Vector3d(-f, 0.0, 0.0); // the gradient of -f x
      ContactSums sums;
      sums.mean_force = f;
      return sums;
    }
    ContactSums
    assemble(Eigen::VectorXd &F, BlockSparseMatrix &K) override
    {
      K.reinit(1, {});
      K.set_zero();
      double *b = K.block(K.diagonal_slot(0));
      b[0] = b[4] = b[8] = k;
      return residual(F);
    }
    bool
    limit_closing(const Eigen::VectorXd &, Eigen::VectorXd &) const override
    {
      return false;
    }

    Eigen::Vector3d x           = Eigen::Vector3d::Zero();
    int             evaluations = 0;
  };

  std::vector<Relaxation *>
  both(FireRelaxation &fire, LbfgsRelaxation &lbfgs)
  {
    return {static_cast<Relaxation *>(&fire),
            static_cast<Relaxation *>(&lbfgs)};
  }
} // namespace

/// A relaxation that cannot approach balance gives up once the window has
/// passed without progress, long before its budget; with the test off, it
/// spends the whole budget. FIRE counts iterations, so it stops at the
/// window exactly; L-BFGS stops at the first accepted step beyond it.
TEST(RelaxationStall, ARelaxationThatCannotBalanceGivesUpAfterTheWindow)
{
  const int       window = 300, budget = 100000;
  FireRelaxation  fire;
  LbfgsRelaxation lbfgs;
  for (Relaxation *minimiser : both(fire, lbfgs))
    {
      EndlessSlope slope;
      minimiser->give_up_when_stalled(window);
      const FireResult r = minimiser->relax(slope, 1e-2, budget);
      EXPECT_FALSE(r.converged);
      EXPECT_TRUE(r.stalled);
      EXPECT_GE(r.iterations, window);
      EXPECT_LT(r.iterations, window + 50);
      EXPECT_GT(slope.x[0], 0.0); // it went downhill all the while

      EndlessSlope unlimited;
      minimiser->give_up_when_stalled(0);
      const FireResult u = minimiser->relax(unlimited, 1e-2, 5 * window);
      EXPECT_FALSE(u.converged);
      EXPECT_FALSE(u.stalled);
      EXPECT_GE(u.iterations, 5 * window);
    }
}

/// A relaxation that keeps halving its distance to balance within the
/// window is not touched by the test: a column of six Material 1 spheres
/// (and a rattler) squeezed by 0.2 R relaxes to 1e-9 of its contact force in
/// the same evaluations and to the same positions, to the bit, with a window of
/// a quarter of its evaluations as without one. A window of one evaluation
/// stops it early, unbalanced.
TEST(RelaxationStall, ARelaxationThatApproachesBalanceIsNotStopped)
{
  const ContactModel model = compax::testing::material1::contact_model();
  const auto         column
    = []() { return compax::testing::sphere_column(6, R, 0.2 * R); };
  FireRelaxation  fire;
  LbfgsRelaxation lbfgs;
  for (Relaxation *minimiser : both(fire, lbfgs))
    {
      Bed free_run = column();
      minimiser->give_up_when_stalled(0);
      const FireResult f = minimiser->relax(free_run, model, 1e-9, 1000000);
      ASSERT_TRUE(f.converged);
      ASSERT_GE(f.iterations, 8);

      Bed watched = column();
      minimiser->give_up_when_stalled(f.iterations / 4);
      const FireResult w = minimiser->relax(watched, model, 1e-9, 1000000);
      EXPECT_TRUE(w.converged);
      EXPECT_FALSE(w.stalled);
      EXPECT_EQ(w.iterations, f.iterations);
      for (std::size_t i = 0; i < free_run.particles.size(); ++i)
        EXPECT_EQ(watched.particles.positions[i],
                  free_run.particles.positions[i]);

      Bed impatient = column();
      minimiser->give_up_when_stalled(1);
      const FireResult s = minimiser->relax(impatient, model, 1e-9, 1000000);
      EXPECT_FALSE(s.converged);
      EXPECT_TRUE(s.stalled);
      EXPECT_LT(s.iterations, f.iterations);
    }
}

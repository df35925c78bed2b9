// Penalty contact with Coulomb friction at one point: the traction obeys
// the Coulomb cone and its tangent matches central finite differences in
// stick and in slip, in 2-D and 3-D.
#include "fem/wall_contact.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fem = compax::fem;

namespace
{
  template <int dim>
  void
  check_tangent(const dealii::Tensor<1, dim> &n,
                const dealii::Tensor<1, dim> &du,
                const dealii::Tensor<1, dim> &friction_old,
                const bool                    expect_stick)
  {
    const double eps_n = 1e12, eps_t = 2e11, mu = 0.3, gap0 = -1e-7;
    const auto   r
      = fem::wall_contact<dim>(n, gap0, du, friction_old, eps_n, eps_t, mu);
    ASSERT_GT(r.pressure, 0.0);
    EXPECT_EQ(r.stick, expect_stick);
    // Coulomb: tangential traction within (stick) or on (slip) the cone,
    // normal part -p n.
    EXPECT_LE(r.friction.norm(), mu * r.pressure * (1 + 1e-12));
    if (!expect_stick)
      {
        EXPECT_NEAR(r.friction.norm(), mu * r.pressure, 1e-9 * r.pressure);
      }
    EXPECT_NEAR(r.traction * n, -r.pressure, 1e-9 * r.pressure);
    const double h = 1e-13;
    for (unsigned int j = 0; j < dim; ++j)
      {
        dealii::Tensor<1, dim> dp = du, dm = du;
        dp[j] += h;
        dm[j] -= h;
        const auto rp
          = fem::wall_contact<dim>(n, gap0, dp, friction_old, eps_n, eps_t, mu);
        const auto rm
          = fem::wall_contact<dim>(n, gap0, dm, friction_old, eps_n, eps_t, mu);
        for (unsigned int i = 0; i < dim; ++i)
          EXPECT_NEAR((rp.traction[i] - rm.traction[i]) / (2 * h),
                      r.tangent[i][j],
                      1e-6 * eps_n)
            << "entry " << i << ',' << j;
      }
  }
} // namespace

TEST(WallContact, OpenGapGivesNoTraction)
{
  const dealii::Tensor<1, 2> n({1.0, 0.0});
  const auto                 r = fem::wall_contact<2>(n,
                                      1e-6,
                                      dealii::Tensor<1, 2>({1e-7, 3e-7}),
                                      dealii::Tensor<1, 2>(),
                                      1e12,
                                      1e11,
                                      0.3);
  EXPECT_EQ(r.pressure, 0.0);
  EXPECT_EQ(r.traction.norm(), 0.0);
  EXPECT_EQ(r.tangent.norm(), 0.0);
}

TEST(WallContact, TangentMatchesFiniteDifferencesInStickAndSlip)
{
  // r-z die wall: normal e_r, friction along z.
  const dealii::Tensor<1, 2> n2({1.0, 0.0});
  check_tangent<2>(n2,
                   dealii::Tensor<1, 2>({1e-8, 1e-9}),
                   dealii::Tensor<1, 2>({0.0, 100.0}),
                   true);
  check_tangent<2>(n2,
                   dealii::Tensor<1, 2>({1e-8, 5e-7}),
                   dealii::Tensor<1, 2>({0.0, -100.0}),
                   false);
  // 3-D cylinder wall at 30 degrees: slip direction in the tangent plane.
  const double               c = std::cos(0.5236), s = std::sin(0.5236);
  const dealii::Tensor<1, 3> n3({c, s, 0.0});
  check_tangent<3>(n3,
                   dealii::Tensor<1, 3>({1e-9, 2e-9, 3e-10}),
                   dealii::Tensor<1, 3>({-s * 50.0, c * 50.0, 20.0}),
                   true);
  check_tangent<3>(n3,
                   dealii::Tensor<1, 3>({1e-7, -1e-7, 4e-7}),
                   dealii::Tensor<1, 3>({-s * 50.0, c * 50.0, 20.0}),
                   false);
}

// The face of a concave punch: its gap is the signed distance to the cup
// sphere or the land, with the normal and curvature the Newton tangent of
// the punch contact uses (checked by finite differences).
#include "fem/punch_profile.h"

#include <deal.II/base/point.h>

#include <gtest/gtest.h>

#include <cmath>

namespace fem = compax::fem;

namespace
{
  fem::PunchProfile
  cup()
  {
    fem::PunchProfile p;
    p.cup_depth  = 0.7e-3;
    p.cup_radius = 16e-3;
    return p;
  }
} // namespace

TEST(PunchProfile, FaceIsTheSphericalCupAndTheLand)
{
  const fem::PunchProfile p    = cup();
  const double            land = 5e-3;
  // Centre of the sphere through the cup bottom (0, land + h) with radius
  // R_c; the cup meets the land plane where that sphere does.
  const double zc = land + p.cup_depth - p.cup_radius;
  const double a
    = std::sqrt(p.cup_radius * p.cup_radius - (land - zc) * (land - zc));
  EXPECT_NEAR(p.cup_edge_radius(), a, 1e-15);
  for (const double r : {0.0, 1e-3, 3e-3, 0.999 * a})
    {
      const dealii::Point<2> x(r, land + p.height(r));
      EXPECT_NEAR(std::hypot(x[0], x[1] - zc), p.cup_radius, 1e-15);
      EXPECT_NEAR(p.gap<2>(x, land).gap, 0.0, 1e-15);
    }
  EXPECT_EQ(p.height(a * 1.001), 0.0);
  EXPECT_NEAR(p.height(0.0), p.cup_depth, 1e-18);
  // pi h^2 (3 R_c - h) / 3 is the cap's volume: integrate 2 pi r c(r).
  double       V  = 0.0;
  const int    n  = 20000;
  const double dr = a / n;
  for (int k = 0; k < n; ++k)
    {
      const double r = (k + 0.5) * dr;
      V += 2.0 * M_PI * r * p.height(r) * dr;
    }
  EXPECT_NEAR(V / p.cup_volume(), 1.0, 1e-7);

  fem::PunchProfile too_wide = p;
  too_wide.cup_depth         = 3e-3;
  EXPECT_THROW(too_wide.validate(5e-3), std::invalid_argument);
  EXPECT_NO_THROW(p.validate(5e-3));
}

TEST(PunchProfile, GapIsTheSignedDistanceToTheNearerFace)
{
  const fem::PunchProfile p    = cup();
  const double            land = 5e-3;
  const double            zc   = land + p.cup_depth - p.cup_radius;
  // Under the cup: distance to the sphere (open), above it: overlap.
  for (const double dz : {-2e-5, 3e-6})
    {
      const dealii::Point<3> x(1e-3,
                               0.5e-3,
                               land + p.height(std::hypot(1e-3, 0.5e-3)) + dz);
      const double rho = std::sqrt(1e-6 + 0.25e-6 + (x[2] - zc) * (x[2] - zc));
      const auto   g   = p.gap<3>(x, land);
      EXPECT_NEAR(g.gap, p.cup_radius - rho, 1e-15);
      EXPECT_NEAR(g.curvature, 1.0 / rho, 1e-9 / rho);
      EXPECT_GT(g.normal[2], 0.9);
    }
  // Over the land near the die wall: the land plane.
  const dealii::Point<2> x(4.9e-3, land + 1e-6);
  const auto             g = p.gap<2>(x, land);
  EXPECT_NEAR(g.gap, -1e-6, 1e-18);
  EXPECT_EQ(g.normal[1], 1.0);
  EXPECT_EQ(g.curvature, 0.0);
}

TEST(PunchProfile, NormalAndCurvatureAreTheGapDerivatives)
{
  // d gap / dx = -n and d n / dx = curvature (I - n n), by central
  // differences, at points overlapping the cup.
  const fem::PunchProfile p    = cup();
  const double            land = 5e-3;
  const double            h    = 1e-9;
  for (const dealii::Point<3> x : {dealii::Point<3>(1e-3, 2e-3, 5.6e-3),
                                   dealii::Point<3>(0.0, 0.0, 5.71e-3)})
    {
      const auto g = p.gap<3>(x, land);
      ASSERT_LT(g.gap, 0.0);
      for (unsigned int j = 0; j < 3; ++j)
        {
          dealii::Point<3> xp = x, xm = x;
          xp[j] += h;
          xm[j] -= h;
          const auto   gp = p.gap<3>(xp, land), gm = p.gap<3>(xm, land);
          const double dg = (gp.gap - gm.gap) / (2.0 * h);
          EXPECT_NEAR(dg, -g.normal[j], 1e-6);
          for (unsigned int i = 0; i < 3; ++i)
            {
              const double dn = (gp.normal[i] - gm.normal[i]) / (2.0 * h);
              const double expected
                = g.curvature
                  * ((i == j ? 1.0 : 0.0) - g.normal[i] * g.normal[j]);
              EXPECT_NEAR(dn, expected, 1e-4 * g.curvature);
            }
        }
    }
}

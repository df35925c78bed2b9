// Hertz law: closed forms (Johnson 1985, Sec. 4.2), exact stiffness against
// a central finite difference, and the rigid-wall limit of the mixing rules.

#include "dem/contact/hertz.h"
#include "dem/contact/pair_properties.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax::dem;

TEST(HertzLaw, ForceAndRadiusOfTwoEqualSpheresMatchJohnson)
{
  const double R = 1e-3, E = 1e9, nu = 0.3, gamma = 2e-6;
  const auto   law = HertzLaw::for_pair(R, E, nu, R, E, nu);
  // Two equal spheres: R* = R/2, E* = E / (2 (1 - nu^2)).
  const double R_star = R / 2, E_star = E / (2 * (1 - nu * nu));
  const auto   r = law.evaluate(gamma, ContactHistory{});
  EXPECT_NEAR(r.force,
              4.0 / 3.0 * E_star * std::sqrt(R_star) * std::pow(gamma, 1.5),
              1e-12 * r.force);
  EXPECT_NEAR(r.contact_radius, std::sqrt(R_star * gamma), 1e-18);
  EXPECT_EQ(law.evaluate(-1e-9, ContactHistory{}).force, 0.0);
}

TEST(HertzLaw, StiffnessEqualsCentralFiniteDifference)
{
  const auto law = HertzLaw::for_pair(1e-3, 2e9, 0.2, 2e-3, 7e9, 0.35);
  for (double gamma = 1e-8; gamma < 1e-4; gamma *= 1.7)
    {
      const double h = 1e-5 * gamma;
      const double fd
        = (law.response(gamma + h).force - law.response(gamma - h).force)
          / (2 * h);
      EXPECT_NEAR(law.response(gamma).stiffness, fd, 1e-6 * std::abs(fd))
        << "gamma = " << gamma;
    }
}

TEST(HertzLaw, WallIsTheLimitOfAHugeStiffSphere)
{
  const double R = 1e-3, E = 1e9, nu = 0.25, gamma = 1e-6;
  const auto   wall = HertzLaw::for_pair(R, E, nu, rigid, rigid, 0.0);
  const auto   big  = HertzLaw::for_pair(R, E, nu, 1e12 * R, 1e12 * E, 0.0);
  EXPECT_NEAR(wall.response(gamma).force,
              big.response(gamma).force,
              1e-9 * wall.response(gamma).force);
  EXPECT_DOUBLE_EQ(wall.effective_radius(), R);
  EXPECT_DOUBLE_EQ(wall.effective_modulus(), E / (1 - nu * nu));
}

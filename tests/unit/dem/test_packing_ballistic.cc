#include "dem/neighbors/cell_grid.h"
#include "dem/packing/ballistic_deposition.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax::dem;

namespace
{
  void
  check_packing(const ParticleSystem &p, double D)
  {
    const double tol = 1e-9;
    // No overlaps beyond tolerance; count supports below each sphere.
    std::vector<int> supports(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        const double R = p.radii[i];
        EXPECT_GE(p.positions[i][2], R * (1 - tol)) << i;
        EXPECT_LE(std::hypot(p.positions[i][0], p.positions[i][1]) + R,
                  0.5 * D * (1 + tol))
          << i;
        if (p.positions[i][2] <= R * (1 + 1e-6))
          ++supports[i];
      }
    for (const auto &[i, j] :
         brute_force_pairs(p.positions, p.radii, 1e-6 * 220e-6))
      {
        const double s = p.radii[i] + p.radii[j];
        const double d = (p.positions[i] - p.positions[j]).norm();
        EXPECT_GE(d, s * (1 - tol)) << i << " " << j;
        // j was placed after i; j rests on i if i is below.
        if (p.positions[i][2] < p.positions[j][2])
          ++supports[j];
        else
          ++supports[i];
      }
    for (std::size_t i = 0; i < p.size(); ++i)
      EXPECT_GE(supports[i], 1) << "particle " << i << " floats";
  }
} // namespace

TEST(PackingBallistic, MonodisperseRestsInsideDieWithoutOverlap)
{
  DepositionParameters prm;
  prm.n_particles        = 400;
  prm.die_diameter       = 4e-3;
  prm.seed               = 5;
  const ParticleSystem p = ballistic_deposition(prm);
  ASSERT_EQ(p.size(), 400u);
  check_packing(p, prm.die_diameter);
  // A random loose packing: the bed's packing fraction below its top
  // layer lies between random loose (~0.55) and dense (0.64) packing
  // corrected for the wall effect; at least not absurd.
  double z_max = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    z_max = std::max(z_max, p.positions[i][2] + p.radii[i]);
  const double rho
    = p.solid_volume()
      / (3.14159265358979 * 0.25 * prm.die_diameter * prm.die_diameter * z_max);
  EXPECT_GT(rho, 0.40);
  EXPECT_LT(rho, 0.64);
}

TEST(PackingBallistic, LogNormalWithCutOffsAndTwoMaterials)
{
  DepositionParameters prm;
  prm.n_particles         = 300;
  prm.die_diameter        = 4e-3;
  prm.sizes.median_radius = 150e-6;
  prm.sizes.log_sigma     = 0.3;
  prm.sizes.min_radius    = 100e-6;
  prm.sizes.max_radius    = 220e-6;
  prm.material_fractions  = {0.5, 0.5};
  prm.seed                = 9;
  const ParticleSystem p  = ballistic_deposition(prm);
  check_packing(p, prm.die_diameter);
  int n1 = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      EXPECT_GE(p.radii[i], 100e-6);
      EXPECT_LE(p.radii[i], 220e-6);
      n1 += p.materials[i] == 1;
    }
  EXPECT_GT(n1, 100);
  EXPECT_LT(n1, 200);
}

TEST(PackingBallistic, SameSeedSamePacking)
{
  DepositionParameters prm;
  prm.n_particles        = 150;
  prm.seed               = 77;
  const ParticleSystem a = ballistic_deposition(prm);
  const ParticleSystem b = ballistic_deposition(prm);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.radii, b.radii);
  prm.seed               = 78;
  const ParticleSystem c = ballistic_deposition(prm);
  EXPECT_NE(a.positions, c.positions);
}

TEST(PackingBallistic, PeriodicColumnWrapsWithoutOverlapOrFloatingSpheres)
{
  // A column periodic in x and y: no overlap with any lateral image, every
  // sphere inside [-L/2, L/2)^2 and resting on the floor or a sphere
  // (possibly across the periodic faces).
  DepositionParameters prm;
  prm.n_particles        = 300;
  prm.die_diameter       = 2.2e-3; // five diameters
  prm.container          = DepositionContainer::periodic_square;
  prm.seed               = 3;
  const ParticleSystem p = ballistic_deposition(prm);
  ASSERT_EQ(p.size(), 300u);
  const double     L = prm.die_diameter, tol = 1e-9;
  std::vector<int> supports(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      const double R = p.radii[i];
      EXPECT_GE(p.positions[i][2], R * (1 - tol)) << i;
      for (int k = 0; k < 2; ++k)
        {
          EXPECT_GE(p.positions[i][k], -0.5 * L * (1 + tol)) << i;
          EXPECT_LT(p.positions[i][k], 0.5 * L * (1 + tol)) << i;
        }
      if (p.positions[i][2] <= R * (1 + 1e-6))
        ++supports[i];
      for (std::size_t j = 0; j < i; ++j)
        {
          Eigen::Vector3d d = p.positions[i] - p.positions[j];
          for (int k = 0; k < 2; ++k)
            d[k] -= L * std::round(d[k] / L);
          const double s = R + p.radii[j];
          EXPECT_GE(d.norm(), s * (1 - tol)) << i << " " << j;
          if (d.norm() <= s * (1 + 1e-6) && d[2] > 0.0)
            ++supports[i];
        }
    }
  int wrapped_supports = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    EXPECT_GE(supports[i], 1) << "particle " << i << " floats";
  // Some spheres rest on a neighbour across a periodic face (otherwise
  // the wrap-around would not be exercised).
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      {
        const Eigen::Vector3d d = p.positions[i] - p.positions[j];
        const double          s = p.radii[i] + p.radii[j];
        Eigen::Vector3d       w = d;
        for (int k = 0; k < 2; ++k)
          w[k] -= L * std::round(w[k] / L);
        if (w.norm() <= s * (1 + 1e-6) && d.norm() > 2 * s)
          ++wrapped_supports;
      }
  EXPECT_GT(wrapped_supports, 0);
}

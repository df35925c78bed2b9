#include "dem/rve/deposited_packing.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax::dem;

namespace
{
  constexpr double pi = 3.14159265358979323846;
}

TEST(DepositedPacking, ExactCountNoOverlapAcrossAnyPeriodicFace)
{
  DepositedPackingSpec spec;
  spec.particle_count = 150;
  spec.seed           = 4;
  const PeriodicBed b = make_deposited_packing(spec);
  const auto       &p = b.particles;
  ASSERT_EQ(p.size(), 150u);
  // Every pair at its shortest image in all three directions: touching at
  // most (the deposit's spheres touch, the cut adds no overlap).
  int touching = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      {
        const double d
          = b.cell.minimum_image(p.positions[i] - p.positions[j]).norm();
        const double s = p.radii[i] + p.radii[j];
        EXPECT_GE(d, s * (1 - 1e-9)) << i << " " << j;
        touching += d <= s * (1 + 1e-6);
      }
  // A deposit is a connected network of touching spheres: at least one
  // contact per sphere on average (each rests on one to three).
  EXPECT_GT(2.0 * touching / p.size(), 1.0);
  // Fully periodic, undeformed, virgin.
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(b.cell.periodic(k));
  EXPECT_TRUE(b.deformation.isIdentity());
  // Solid fraction of a loose random packing of equal spheres: above random
  // sequential addition's 0.38, below random close packing's 0.64.
  const double solid = 150 * 4.0 / 3.0 * pi * std::pow(220e-6, 3);
  EXPECT_NEAR(b.relative_density(), solid / b.cell.volume(), 1e-12);
  EXPECT_GT(b.relative_density(), 0.38);
  EXPECT_LT(b.relative_density(), 0.64);
}

TEST(DepositedPacking, SameSeedSameCell)
{
  DepositedPackingSpec spec;
  spec.particle_count = 80;
  spec.seed           = 11;
  const PeriodicBed a = make_deposited_packing(spec);
  const PeriodicBed b = make_deposited_packing(spec);
  EXPECT_EQ(a.particles.positions, b.particles.positions);
  EXPECT_EQ(a.cell.lattice(), b.cell.lattice());
  spec.seed           = 12;
  const PeriodicBed c = make_deposited_packing(spec);
  EXPECT_NE(a.particles.positions, c.particles.positions);
}

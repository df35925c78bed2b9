// The periodic cell: wrapping and minimum image on a skewed lattice, the
// periodic linked-cell search against trying every image, contacts across
// the boundary in the dynamics, the size distribution fit (Table 1) and
// the random insertion.

#include "dem/dynamics/explicit_dem.h"
#include "dem/packing/random_source.h"
#include "dem/periodic/periodic_cell.h"
#include "dem/periodic/periodic_pairs.h"
#include "dem/periodic/random_insertion.h"
#include "dem/periodic/size_distribution_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace compax::dem;

namespace
{
  Eigen::Matrix3d
  skewed_lattice()
  {
    Eigen::Matrix3d H;
    H << 1.0e-3, 0.2e-3, 0.1e-3, //
      0.0, 0.9e-3, -0.15e-3,     //
      0.05e-3, 0.0, 1.1e-3;
    return H;
  }
} // namespace

TEST(PeriodicCell, WrapAndMinimumImageOnASkewedLattice)
{
  const PeriodicCell cell(skewed_lattice(), {true, true, true});
  RandomSource       random(3);
  for (int k = 0; k < 200; ++k)
    {
      const Eigen::Vector3d x(random.uniform(-5e-3, 5e-3),
                              random.uniform(-5e-3, 5e-3),
                              random.uniform(-5e-3, 5e-3));
      Eigen::Vector3d       y = x;
      const LatticeImage    n = cell.wrap(y);
      const Eigen::Vector3d s = cell.fractional(y);
      for (int d = 0; d < 3; ++d)
        {
          EXPECT_GE(s[d], -1e-12);
          EXPECT_LT(s[d], 1.0 + 1e-12);
        }
      EXPECT_LT((y + cell.image_offset(n) - x).norm(), 1e-15);

      // A short separation: the minimum image is the shortest of all.
      const Eigen::Vector3d d = 0.3e-3
                                  * Eigen::Vector3d(random.uniform(-1, 1),
                                                    random.uniform(-1, 1),
                                                    random.uniform(-1, 1))
                                + cell.image_offset({int(k % 3) - 1, 2, -1});
      double best = 1e300;
      for (int a = -3; a <= 3; ++a)
        for (int b = -3; b <= 3; ++b)
          for (int c = -3; c <= 3; ++c)
            best = std::min(best, (d + cell.image_offset({a, b, c})).norm());
      EXPECT_NEAR(cell.minimum_image(d).norm(), best, 1e-15);
    }
  // Widths: |det H| / |a_j x a_k|; for a box they are the edges.
  const PeriodicCell box
    = PeriodicCell::box(Eigen::Vector3d(1.0, 2.0, 3.0), {true, true, false});
  EXPECT_DOUBLE_EQ(box.width(1), 2.0);
  EXPECT_DOUBLE_EQ(box.volume(), 6.0);
  EXPECT_FALSE(box.periodic(2));
}

TEST(PeriodicCellGrid, FindsTheSamePairsAsTryingEveryImage)
{
  struct Case
  {
    PeriodicCell cell;
    double       r_min, r_max;
    int          n;
  };
  const std::vector<Case> cases{
    // Many bins, plates in z.
    {PeriodicCell::box(Eigen::Vector3d(2e-3, 1.5e-3, 1e-3),
                       {true, true, false}),
     30e-6,
     90e-6,
     600},
    // One to two bins per direction: several images of one pair touch.
    {PeriodicCell::box(Eigen::Vector3d(0.4e-3, 0.6e-3, 2e-3),
                       {true, true, false}),
     40e-6,
     180e-6,
     60},
    // Fully periodic and skewed.
    {PeriodicCell(skewed_lattice(), {true, true, true}), 30e-6, 120e-6, 150}};
  RandomSource     random(11);
  PeriodicCellGrid grid;
  for (const Case &c : cases)
    {
      std::vector<Eigen::Vector3d> x;
      std::vector<double>          r;
      for (int k = 0; k < c.n; ++k)
        {
          // Unwrapped positions up to two cells away.
          const Eigen::Vector3d s(random.uniform(-2, 3),
                                  random.uniform(-2, 3),
                                  c.cell.periodic(2) ? random.uniform(-2, 3)
                                                     : random.uniform(0, 1));
          x.push_back(c.cell.lattice() * s);
          r.push_back(random.uniform(c.r_min, c.r_max));
        }
      const double           margin = 10e-6;
      std::vector<ImagePair> found;
      grid.find_pairs(c.cell, x, r, margin, found);
      // Unwrapped positions 2 cells out: images up to 5 cells apart.
      const auto expected = brute_force_image_pairs(c.cell, x, r, margin, 6);
      ASSERT_FALSE(expected.empty());
      EXPECT_EQ(found, expected);
    }
}

TEST(PeriodicDynamics, ContactAcrossTheBoundaryKeepsItsHistory)
{
  // Two spheres pressed together across x = 0 of a periodic box, moving
  // on through the boundary together: the contact is one and the same
  // (its delta_max survives every neighbour rebuild) and the forces are
  // equal and opposite along the minimum-image normal.
  DemMaterial m;
  m.particle_particle                    = {1.0, 0.0, 0.0};
  m.normal_law.unloading_stiffness_ratio = 5.0;
  m.normal_law.plasticity_depth          = 0.02;
  const double L = 1e-3, R = 100e-6;
  ExplicitDem  dem(m,
                  PeriodicCell::box(Eigen::Vector3d(L, L, L),
                                    {true, true, false}));
  dem.add_particle(Eigen::Vector3d(R - 1e-6, 0.5 * L, 0.5 * L), R);
  dem.add_particle(Eigen::Vector3d(L - R + 2e-6, 0.5 * L, 0.5 * L), R);
  dem.set_kinematic(0, true);
  dem.set_kinematic(1, true);
  auto &p = dem.particles();
  dem.step();
  ASSERT_EQ(dem.contact_count(), 1u);
  const double delta = dem.pair_contacts()[0].overlap;
  EXPECT_NEAR(delta, 3e-6, 1e-12);
  EXPECT_NEAR(p.force[0][0], -p.force[1][0], 1e-12 * std::abs(p.force[0][0]));
  EXPECT_GT(p.force[0][0], 0.0); // pushed to +x, away from its image partner
  // Move both by two box lengths in -x.
  p.velocity[0] = p.velocity[1] = Eigen::Vector3d(-1.0, 0.0, 0.0);
  dem.set_fixed_time_step(2e-6);
  for (int k = 0; k < 1000; ++k)
    dem.step();
  EXPECT_GT(dem.neighbour_rebuilds(), 10u);
  ASSERT_EQ(dem.contact_count(), 1u);
  EXPECT_NEAR(dem.pair_contacts()[0].overlap, delta, 1e-12);
  EXPECT_NEAR(MulticontactAdhesiveLaw::delta_max(
                dem.pair_contacts()[0].history),
              delta,
              1e-12);
}

TEST(SizeDistributionFit, RecoversALogNormalFromItsQuantiles)
{
  const double median = 150e-6, sigma = 0.5, z = 1.2815515655446004;
  const auto   fit = fit_volume_log_normal(median * std::exp(-z * sigma),
                                         median,
                                         median * std::exp(z * sigma));
  EXPECT_NEAR(fit.median_diameter, median, 1e-12 * median);
  EXPECT_NEAR(fit.log_sigma, sigma, 1e-12);
  EXPECT_NEAR(fit.quantile(0.9), median * std::exp(z * sigma), 1e-9 * median);
}

TEST(SizeDistributionFit, NumberSamplesHaveTheFittedVolumeMedian)
{
  // Hatch-Choate: sampling the number distribution with median
  // x50,3 exp(-3 sigma^2) gives a volume-weighted median x50,3.
  const auto   fit = fit_volume_log_normal(82.9e-6, 224.6e-6, 379.3e-6);
  const auto   psd = number_radius_distribution(fit, 0.0, 1.0);
  RandomSource random(5);
  std::vector<std::pair<double, double>> d; // (diameter, volume)
  double                                 total = 0.0;
  for (int k = 0; k < 400000; ++k)
    {
      const double x = 2.0 * psd.sample(random);
      d.emplace_back(x, x * x * x);
      total += x * x * x;
    }
  std::sort(d.begin(), d.end());
  double acc = 0.0, median = 0.0;
  for (const auto &[x, v] : d)
    if ((acc += v) >= 0.5 * total)
      {
        median = x;
        break;
      }
  EXPECT_NEAR(median, fit.median_diameter, 0.03 * fit.median_diameter);
}

TEST(RandomInsertion, FillsTheBoxToThePackingDensity)
{
  const auto    fit = fit_volume_log_normal(82.9e-6, 224.6e-6, 379.3e-6);
  InsertionSpec spec;
  spec.box             = Eigen::Vector3d::Constant(0.8e-3);
  spec.packing_density = 0.59;
  spec.sizes           = number_radius_distribution(fit, 82.9e-6, 379.3e-6);
  RandomSource random(2);
  const auto   a = insert_random(spec, random);
  double       V = 0.0, v_max = 0.0;
  for (std::size_t k = 0; k < a.radii.size(); ++k)
    {
      const double r = a.radii[k], v = 4.0 / 3.0 * std::acos(-1.0) * r * r * r;
      V += v;
      v_max = std::max(v_max, v);
      EXPECT_GE(r, 0.5 * 82.9e-6);
      EXPECT_LE(r, 0.5 * 379.3e-6);
      const Eigen::Vector3d &x = a.positions[k];
      EXPECT_GE(x[0], 0.0);
      EXPECT_LT(x[0], spec.box[0]);
      EXPECT_GE(x[2], spec.initial_scale * r);
      EXPECT_LE(x[2], spec.box[2] - spec.initial_scale * r);
    }
  EXPECT_NEAR(V / spec.box.prod(), 0.59, v_max / spec.box.prod());
  // Reproducible from the seed.
  RandomSource again(2);
  EXPECT_EQ(insert_random(spec, again).positions, a.positions);
  // A given count scales the box to the density.
  spec.particle_count = 50;
  RandomSource third(4);
  const auto   b = insert_random(spec, third);
  ASSERT_EQ(b.radii.size(), 50u);
  double Vb = 0.0;
  for (const double r : b.radii)
    Vb += 4.0 / 3.0 * std::acos(-1.0) * r * r * r;
  EXPECT_NEAR(Vb / b.box.prod(), 0.59, 1e-12);
}

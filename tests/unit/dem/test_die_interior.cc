#include "dem/die/die_compaction.h"
#include "dem/die/die_interior.h"
#include "dem/die/die_setup.h"
#include "tests/support/deposited_die.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  /// A simple cubic lattice of spacing @p a of spheres of radius @p R
  /// filling a die 24 a wide and 12 a high, with its contacts.
  Bed
  cubic_lattice_die(const double R, const double a)
  {
    Bed bed;
    bed.walls.diameter    = 24 * a;
    bed.walls.lower_punch = 0.0;
    bed.walls.upper_punch = 12 * a;
    for (int i = -11; i <= 11; ++i)
      for (int j = -11; j <= 11; ++j)
        for (int k = 0; k < 12; ++k)
          {
            const Eigen::Vector3d x(i * a, j * a, (k + 0.5) * a);
            if (x.head<2>().norm() < bed.walls.radius() - R)
              bed.particles.add(x, R);
          }
    bed.contacts = ContactSet(0.3 * R);
    bed.contacts.rebuild(bed.particles, bed.walls, material1::contact_model());
    return bed;
  }
} // namespace

/// A simple cubic lattice of equal spheres overlapping by gamma fills a die.
/// Every interior sphere has six contacts of force P at +-a/2 along the
/// axes (a = 2R - gamma), so its moment sum_c (x_c - x) (x) f_c is
/// -P a I: sigma / rho = -P a / (4/3 pi R^3) exactly, whatever the region
/// cuts off, sigma_rr = sigma_zz (isotropic), and rho is the number of
/// centres in the region times a sphere's volume over the region's volume.
TEST(DieInterior, CubicLatticeGivesTheClosedForm)
{
  const double R = 1e-4, gamma = 2e-7, a = 2 * R - gamma;
  const Bed    bed = cubic_lattice_die(R, a);
  ASSERT_FALSE(bed.contacts.pairs.empty());
  const double P = bonded_law(bed.contacts.pairs.front().law)
                     .response(gamma, 0.0, 0.0)
                     .force;
  ASSERT_GT(P, 0.0);

  const double           w = 4 * R;
  const InteriorMeasures m
    = measure_interior(bed, w, 0.0, 0.0, InteriorWeighting::sphere_centres);
  // The centres in the region, counted independently.
  const double r_max = bed.walls.radius() - w;
  std::size_t  n     = 0;
  for (const Eigen::Vector3d &x : bed.particles.positions)
    n += x.z() > w && x.z() < bed.walls.upper_punch - w
         && x.head<2>().norm() < r_max;
  ASSERT_GT(n, 100u);
  EXPECT_EQ(m.particles, n);
  const double volume = pi * r_max * r_max * (bed.walls.upper_punch - 2 * w);
  const double sphere = 4.0 / 3.0 * pi * R * R * R;
  EXPECT_NEAR(m.relative_density, n * sphere / volume, 1e-12);
  EXPECT_NEAR(m.sigma_zz / m.relative_density,
              -P * a / sphere,
              1e-9 * P * a / sphere);
  EXPECT_NEAR(m.sigma_rr, m.sigma_zz, 1e-9 * std::abs(m.sigma_zz));

  // A region that holds no centre gives no numbers.
  const InteriorMeasures empty = measure_interior(
    bed, 6.5 * a, 0.0, 0.0, InteriorWeighting::sphere_centres);
  EXPECT_EQ(empty.particles, 0u);
  EXPECT_TRUE(std::isnan(empty.sigma_zz));
  // Nor does one lower than the extent asked for.
  const double height = bed.walls.upper_punch - 2 * w;
  EXPECT_EQ(measure_interior(
              bed, w, 0.0, 1.01 * height, InteriorWeighting::sphere_centres)
              .particles,
            0u);
  EXPECT_EQ(measure_interior(
              bed, w, 0.0, 0.99 * height, InteriorWeighting::sphere_centres)
              .particles,
            n);
}

/// With no wall distance the region is the whole die, and the moments of
/// the pair forces cancel: the Love-Weber sum reduces to the wall forces
/// times their contact points, sigma_zz V = -F_u z_u + F_l z_l = -F H for a
/// frictionless die in equilibrium. So sigma_zz is minus the punch
/// pressure, up to the contact points' offset from the punch faces (half
/// an overlap) and the residual forces (bounded as in DieProtocol), and the
/// solid fraction is the die's relative density.
TEST(DieInterior, WholeDieStressIsThePunchPressure)
{
  Bed                bed   = compax::testing::deposited_die(150, 3e-3, 3);
  const ContactModel model = material1::contact_model();
  DieProtocol        protocol;
  protocol.compaction_targets
    = density_targets(bed.relative_density(), 0.75, 12);
  protocol.eject = false;
  DieCompaction die(bed, model, protocol);
  ASSERT_NO_THROW(die.run());
  const Bed       &state = die.bed();
  const DieRecord &last  = die.records().back();
  ASSERT_EQ(last.relaxed, 0);

  const InteriorMeasures m
    = measure_interior(state, 0.0, 0.0, 0.0, InteriorWeighting::sphere_centres);
  EXPECT_EQ(m.particles, state.particles.size());
  EXPECT_NEAR(m.relative_density, state.relative_density(), 1e-12);
  // sum_i m_i = sum_walls x_c (x) f_c - sum_i x_i (x) r_i (r_i: residual
  // force). A punch contact of force P and overlap gamma acts at half an
  // overlap beyond the punch face, so sigma_zz V = -F_u z_u + F_l z_l -
  // sum_punch P gamma / 2 - sum_i z_i r_i,z, the last term bounded by N
  // max|r_i| max|z_i|.
  double offset = 0.0;
  for (const WallContact &c : state.contacts.walls)
    {
      if (c.wall == Wall::die)
        continue;
      const WallGap g = state.walls.gap(c.wall,
                                        state.particles.positions[c.i],
                                        state.particles.radii[c.i]);
      offset += 0.5 * g.overlap
                * bonded_law(c.law)
                    .response(g.overlap,
                              BondedElastoplasticLaw::a_p(c.history),
                              BondedElastoplasticLaw::a_B(c.history))
                    .force;
    }
  const double V = state.walls.enclosed_volume();
  const double z = std::max(std::abs(state.walls.lower_punch),
                            std::abs(state.walls.upper_punch));
  const double expected
    = (-last.upper_punch_force * state.walls.upper_punch
       + last.lower_punch_force * state.walls.lower_punch - offset)
      / V;
  const double bound
    = state.particles.size() * last.residual * last.mean_contact_force * z / V;
  const double p = last.upper_punch_pressure;
  ASSERT_GT(p, 1e6);
  EXPECT_NEAR(m.sigma_zz, expected, bound + 1e-9 * p);
  // The offset is what separates the Love-Weber stress from the punch
  // pressure: small, and the check resolves it.
  EXPECT_LT(offset / V, 0.05 * p);
  EXPECT_LT(bound, 1e-3 * offset / V);
}

/// The part of a sphere inside the die's interior region against closed
/// forms (whole, none, a spherical cap pi h^2 (3R - h) / 3 cut by a punch
/// plane) and, where the cylinder cuts it, against an independent count of
/// the points of a fine grid over the sphere's bounding cube.
TEST(DieInterior, VolumeInRegionMatchesCapsAndAGridCount)
{
  const double R = 1e-4, r_max = 2e-3, z_lo = 1e-3, z_hi = 3e-3;
  const double sphere = 4.0 / 3.0 * pi * R * R * R;
  const auto   in     = [&](const Eigen::Vector3d &x) {
    return volume_in_die_region(x, R, r_max, z_lo, z_hi);
  };
  EXPECT_NEAR(in({0.0, 0.0, 2e-3}), sphere, 1e-12 * sphere);
  EXPECT_NEAR(in({0.0, 0.0, z_hi + R}), 0.0, 1e-12 * sphere);
  EXPECT_EQ(in({r_max + R, 0.0, 2e-3}), 0.0);
  for (const double h : {0.1 * R, 0.5 * R, R, 1.7 * R})
    {
      const double cap = pi * h * h * (3.0 * R - h) / 3.0;
      EXPECT_NEAR(in({0.0, 0.0, z_lo + h - R}), cap, 1e-12 * sphere);
      EXPECT_NEAR(in({1e-3, 0.0, z_hi - h + R}), cap, 1e-12 * sphere);
    }

  // Cut by the cylinder only, and by the cylinder and a punch plane.
  const int n = 200;
  for (const Eigen::Vector3d &x :
       {Eigen::Vector3d(r_max - 0.3 * R, 0.0, 2e-3),
        Eigen::Vector3d(0.6 * r_max, 0.8 * r_max, 2e-3),
        Eigen::Vector3d(0.0, r_max + 0.4 * R, 2e-3),
        Eigen::Vector3d(r_max, 0.0, z_lo + 0.2 * R)})
    {
      const double h     = 2.0 * R / n;
      std::size_t  count = 0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          for (int k = 0; k < n; ++k)
            {
              const Eigen::Vector3d y = x
                                        + Eigen::Vector3d(-R + (i + 0.5) * h,
                                                          -R + (j + 0.5) * h,
                                                          -R + (k + 0.5) * h);
              count += (y - x).norm() < R && y.head<2>().norm() < r_max
                       && y.z() > z_lo && y.z() < z_hi;
            }
      // The grid's error is of the order of its surface cells.
      EXPECT_NEAR(in(x), count * h * h * h, 2e-3 * sphere) << x.transpose();
    }
}

/// Weighted by their volume inside, the spheres of the cubic lattice still
/// all carry the moment -P a I: sigma / rho = -P a / (4/3 pi R^3) whatever
/// the region cuts; and a region whose height is a whole number of
/// lattice spacings holds the lattice's solid fraction (4/3 pi R^3) / a^3
/// up to the cut of the cylinder through the lattice (a disc of radius
/// ~7.6 a sampling a square lattice).
TEST(DieInterior, VolumeWeightsKeepTheLatticeClosedForm)
{
  const double R = 1e-4, gamma = 2e-7, a = 2 * R - gamma;
  const Bed    bed = cubic_lattice_die(R, a);
  const double P   = bonded_law(bed.contacts.pairs.front().law)
                     .response(gamma, 0.0, 0.0)
                     .force;
  const double sphere = 4.0 / 3.0 * pi * R * R * R;

  for (const double w : {2.0 * a, 2.0 * a + 0.3 * R, 2.0 * a + 0.7 * R})
    {
      const InteriorMeasures m = measure_interior(bed, w);
      ASSERT_GT(m.particles, 100u);
      EXPECT_NEAR(m.sigma_zz / m.relative_density,
                  -P * a / sphere,
                  1e-9 * P * a / sphere);
      EXPECT_NEAR(m.sigma_rr, m.sigma_zz, 1e-9 * std::abs(m.sigma_zz));
    }
  const InteriorMeasures m = measure_interior(bed, 2.0 * a);
  EXPECT_NEAR(m.relative_density,
              sphere / (a * a * a),
              5e-3 * sphere / (a * a * a));
}

/// Every sphere of the cubic lattice that the region reaches has its six
/// loaded neighbours, so the interior's coordination number is 6 whichever
/// weights count the spheres (up to the rounding of the weighted mean).
TEST(DieInterior, LatticeCoordinationIsSix)
{
  const double R = 1e-4, a = 2 * R - 2e-7;
  const Bed    bed = cubic_lattice_die(R, a);
  for (const InteriorWeighting weighting :
       {InteriorWeighting::volume_fraction, InteriorWeighting::sphere_centres})
    {
      const InteriorMeasures m
        = measure_interior(bed, 2.0 * a, 0.0, 0.0, weighting);
      ASSERT_GT(m.particles, 100u);
      EXPECT_NEAR(m.coordination_number, 6.0, 1e-12);
    }
}

#include "dem/nonlocal/two_material_bed.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax;

namespace
{
  dem::BedCompactionPoint
  point(double rho, double load, double lateral, bool jammed)
  {
    dem::BedCompactionPoint p;
    p.relative_density                        = rho;
    p.wall_force[dem::SquareDie::upper_punch] = load;
    p.lateral_force                           = lateral;
    p.jammed                                  = jammed;
    return p;
  }
} // namespace

TEST(TwoMaterialBed, CountsGiveTheRequestedSolidVolumeFraction)
{
  dem::TwoMaterialBed bed;
  bed.sizes[0].median_radius = 80e-6;
  bed.sizes[1].median_radius = 160e-6; // 8 times the volume
  bed.sizes[0].log_sigma = bed.sizes[1].log_sigma = 0.0;
  // A monodisperse sphere's mean volume is 4/3 pi R^3.
  EXPECT_NEAR(dem::mean_sphere_volume(bed.sizes[0]),
              4.0 / 3.0 * M_PI * std::pow(80e-6, 3),
              1e-12 * std::pow(80e-6, 3));
  for (const double f : {0.0, 0.25, 0.5, 0.9})
    {
      bed.volume_fraction_2 = f;
      const auto n          = dem::material_counts(bed, 9000);
      EXPECT_EQ(n[0] + n[1], 9000u);
      // n2 v2 / (n1 v1 + n2 v2) = f to the rounding of one particle.
      const double v1 = 1.0, v2 = 8.0;
      const double got = n[1] * v2 / (n[0] * v1 + n[1] * v2);
      EXPECT_NEAR(got, f, v2 / (9000.0 * v1)) << "f = " << f;
    }
}

TEST(TwoMaterialBed, DiscrepanciesAreRelativeToHertzAtCommonDensities)
{
  dem::BedCompactionResult hertz, nonlocal;
  hertz.points    = {point(0.50, 0.0, 0.0, false),
                     point(0.60, 2.0, 1.0, true),
                     point(0.70, 4.0, 2.0, true)};
  nonlocal.points = {point(0.50, 0.0, 0.0, false), point(0.60, 3.0, 1.5, true)};
  const auto rows = dem::formulation_discrepancies(hertz, nonlocal);
  ASSERT_EQ(rows.size(), 2u);             // 0.70 has no nonlocal point
  EXPECT_FALSE(rows[0].load_discrepancy); // not jammed
  EXPECT_FALSE(rows[0].lateral_discrepancy);
  ASSERT_TRUE(rows[1].load_discrepancy);
  EXPECT_DOUBLE_EQ(*rows[1].load_discrepancy, 0.5);
  EXPECT_DOUBLE_EQ(*rows[1].lateral_discrepancy, 0.5);
  // The same result against itself differs by nothing.
  for (const auto &r : dem::formulation_discrepancies(hertz, hertz))
    if (r.load_discrepancy)
      {
        EXPECT_EQ(*r.load_discrepancy, 0.0);
      }
}

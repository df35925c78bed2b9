#include "coupling/dpc_calibration.h"
#include "fem/dpc_table.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax::coupling;

/// Forward: the point of a known cap where the outward normal has the
/// uniaxial-strain direction; the fit must return that cap.
TEST(DpcCalibration, CapThroughUniaxialStateRecoversKnownCap)
{
  for (const double R : {0.3, 0.6, 1.2})
    for (const double tb : {0.0, 0.8, 1.5})
      {
        const double d = 2e6, pb = 80e6;
        const double pa = (pb - R * d) / (1.0 + R * tb);
        // Parametrize the cap (p, q) = (p_a + r cos phi, r sin phi / R),
        // r = R (d + p_a tan beta), and find the angle whose normal
        // ((p - p_a), R^2 q) has the ratio 2/3 by bisection on phi.
        const double r   = R * (d + pa * tb);
        auto         rat = [&](double phi) {
          const double p = pa + r * std::cos(phi), q = r * std::sin(phi) / R;
          return R * R * q / (p - pa) - 2.0 / 3.0;
        };
        double lo = 1e-9, hi = M_PI / 2 - 1e-9;
        for (int it = 0; it < 200; ++it)
          {
            const double mid           = 0.5 * (lo + hi);
            (rat(mid) < 0.0 ? lo : hi) = mid;
          }
        const double           phi = 0.5 * (lo + hi);
        const StressInvariants s{pa + r * std::cos(phi), r * std::sin(phi) / R};
        // The point is on the cap: F_c = 0.
        EXPECT_NEAR(std::hypot(s.p - pa, R * s.q), r, 1e-9 * r);
        const CapParameters c = cap_through_uniaxial_state(s, {d, tb});
        EXPECT_NEAR(c.eccentricity, R, 1e-9 * R);
        EXPECT_NEAR(c.cap_pressure, pb, 1e-9 * pb);
        EXPECT_NEAR(c.cap_origin, pa, 1e-9 * pb);
      }
}

TEST(DpcCalibration, ShearLineThroughTwoPoints)
{
  const ShearLine l = shear_line_through({1e6, 3e6}, {5e6, 7e6});
  EXPECT_DOUBLE_EQ(l.tan_friction_angle, 1.0);
  EXPECT_DOUBLE_EQ(l.cohesion, 2e6);
  EXPECT_THROW(shear_line_through({1e6, 3e6}, {1e6, 7e6}), std::domain_error);
}

/// A cap lies below the shear line; a state above it has no cap.
TEST(DpcCalibration, StateAboveShearLineIsRejected)
{
  EXPECT_THROW(cap_through_uniaxial_state({1e6, 20e6}, {5e6, 1.0}),
               std::domain_error);
}

/// Table cap pressures that give the fitted caps at the plastic densities:
/// the table's own interpolation (fem::DpcTable) returns each fitted cap
/// at its plastic density, below, inside and above the table; with plastic
/// densities at the rows they are the fitted caps themselves.
TEST(DpcCalibration, CapPressuresAtRowsReproduceCapsAtPlasticDensity)
{
  const std::vector<double> rows = {0.70, 0.75, 0.80, 0.85};
  const std::vector<double> cap  = {5e6, 11e6, 17e6, 26e6};
  for (const double shift : {0.0, 0.004, 0.02})
    {
      std::vector<double> rho_p;
      for (const double r : rows)
        rho_p.push_back(r - shift);
      const std::vector<double> y = cap_pressures_at_rows(rows, rho_p, cap);
      compax::fem::DpcTable     t;
      for (std::size_t k = 0; k < rows.size(); ++k)
        t.add_row(rows[k], 1e6, 40.0, 0.8, y[k], 1e9, 0.3);
      t.validate();
      for (std::size_t k = 0; k < rows.size(); ++k)
        {
          double pb, dpb;
          t.cap_pressure(rho_p[k], pb, dpb);
          EXPECT_NEAR(pb, cap[k], 1e-10 * cap[k]) << shift << " " << k;
          if (shift == 0.0)
            EXPECT_NEAR(y[k], cap[k], 1e-10 * cap[k]);
          else
            EXPECT_GT(y[k], cap[k]); // the cap is reached at a lower density
        }
    }
  // Two plastic densities that the table cannot tell apart.
  EXPECT_THROW(cap_pressures_at_rows(rows, {0.69, 0.69, 0.79, 0.84}, cap),
               std::domain_error);
}

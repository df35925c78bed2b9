// The multi-contact adhesive elasto-plastic law (Giannis 2021, Eqs. 6-14)
// driven through the explicit integrator by imposed motion: the force-
// overlap path of loading, unloading, adhesion and reloading against the
// equations evaluated here independently (with the errata corrected as
// documented in multicontact_adhesive.h), the particle stress and its
// one-step-lagged pressure term, and beta = 0 as the conventional model.

#include "dem/contact/hertz.h"
#include "dem/contact/pair_properties.h"
#include "dem/dynamics/explicit_dem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace compax::dem;

namespace
{
  /// Eqs. (6)-(11) with k2* in Eqs. (7), (9), (11) corrected.
  struct PaperLaw
  {
    double k1, k2, kc, delta_star;

    PaperLaw(double R, double E, double r2, double rc, double phi)
    {
      k1         = 4.0 / 3.0 * E * std::sqrt(R);
      k2         = r2 * k1;
      kc         = rc * k1;
      delta_star = k2 / (k2 - k1) * phi * 2.0 * R;
    }
    double
    k2s(double dm) const
    {
      return dm >= delta_star ? k2 : k1 + (k2 - k1) * dm / delta_star;
    }
    double
    delta0(double dm) const
    {
      return std::pow(1.0 - k1 / k2s(dm), 2.0 / 3.0) * dm;
    }
    double
    delta_min(double dm) const
    {
      return std::pow((k2s(dm) - k1) / (k2s(dm) + kc), 2.0 / 3.0) * dm;
    }
    double
    force(double d, double dm) const
    {
      if (d <= 0.0)
        return 0.0;
      const double x = std::pow(d, 1.5);
      if (d >= dm)
        return k1 * x;
      const double branch = k2s(dm) * (x - std::pow(delta0(dm), 1.5));
      return std::max(branch, -kc * x);
    }
  };

  DemMaterial
  law_material(double r2, double rc, double phi, double beta)
  {
    DemMaterial m;
    m.particle_particle                    = {1.0, 0.0, 0.0};
    m.normal_law.unloading_stiffness_ratio = r2;
    m.normal_law.adhesion_stiffness_ratio  = rc;
    m.normal_law.plasticity_depth          = phi;
    m.normal_law.multicontact_prefactor    = beta;
    return m;
  }

  /// Two kinematic spheres; j moves along x through the turning points of
  /// the overlap. Returns (delta, force, lever-weighted pressure input).
  struct PathPoint
  {
    double delta, force, delta_max;
  };

  std::vector<PathPoint>
  drive(ExplicitDem               &dem,
        const std::vector<double> &turning_overlaps,
        const double               speed)
  {
    auto &p = dem.particles();
    dem.set_kinematic(0, true);
    dem.set_kinematic(1, true);
    const double           Rs = p.radius[0] + p.radius[1];
    std::vector<PathPoint> path;
    double                 dm = 0.0;
    for (const double target : turning_overlaps)
      {
        const double now = Rs - (p.position[1] - p.position[0]).norm();
        const double dir = target > now ? -1.0 : 1.0; // j moves to -x to load
        p.velocity[1]    = Eigen::Vector3d(dir * speed, 0.0, 0.0);
        for (int step = 0; step < 1000000; ++step)
          {
            dem.step();
            const double d = Rs - (p.position[1] - p.position[0]).norm();
            const auto  &c = dem.pair_contacts();
            const double f = c.empty() ? 0.0 : c[0].normal_force;
            path.push_back({d, f, dm});
            if (d > 0.0)
              dm = std::max(dm, d);
            else
              dm = 0.0;
            if ((dir < 0 && d >= target) || (dir > 0 && d <= target))
              break;
          }
      }
    return path;
  }
} // namespace

TEST(MulticontactDynamics, LoadUnloadAdhesionReloadFollowEqs6To11)
{
  const double R1 = 120e-6, R2 = 80e-6;
  const double r2 = 5.0, rc = 0.5, phi = 0.02;
  for (const double peak_fraction : {0.5, 2.0}) // delta_max below/above delta*
    {
      ExplicitDem dem(law_material(r2, rc, phi, 0.0),
                      PeriodicCell::box(Eigen::Vector3d(1e-2, 1e-2, 1e-2),
                                        {true, true, false}));
      dem.add_particle(Eigen::Vector3d(5e-3, 5e-3, 5e-3), R1);
      dem.add_particle(Eigen::Vector3d(5e-3 + R1 + R2 + 1e-7, 5e-3, 5e-3), R2);
      const double   R = R1 * R2 / (R1 + R2);
      const double   E = effective_modulus(2.58e8, 0.3, 2.58e8, 0.3);
      const PaperLaw law(R, E, r2, rc, phi);
      const double   peak = peak_fraction * law.delta_star;
      dem.set_fixed_time_step(peak / 4000.0 / 0.05);
      // Load, unload part way, reload beyond, unload past separation.
      const auto path = drive(dem, {0.7 * peak, 0.3 * peak, peak, -1e-7}, 0.05);

      double worst = 0.0, scale = law.k1 * std::pow(peak, 1.5);
      double f_min = 0.0, d_zero = -1.0;
      for (std::size_t k = 0; k < path.size(); ++k)
        {
          const auto &q = path[k];
          worst         = std::max(worst,
                           std::abs(q.force - law.force(q.delta, q.delta_max)));
          f_min         = std::min(f_min, q.force);
          if (k > 0 && path[k - 1].force > 0.0 && q.force <= 0.0
              && q.delta_max >= peak)
            d_zero = q.delta;
        }
      EXPECT_LT(worst, 1e-9 * scale);
      // Closed forms of the final unloading: zero force at delta_0 (Eq. 7),
      // the most tensile force -kc delta_min^{3/2} (Eqs. 8-9), to the
      // resolution of the imposed path (peak / 4000 per step).
      EXPECT_NEAR(d_zero, law.delta0(peak), peak / 2000.0);
      const double F_min = -law.kc * std::pow(law.delta_min(peak), 1.5);
      EXPECT_NEAR(f_min, F_min, 2e-3 * std::abs(F_min));
      // Eq. (11): the unloading stiffness interpolates below delta*.
      if (peak_fraction < 1.0)
        EXPECT_LT(law.k2s(peak), law.k2);
      else
        EXPECT_EQ(law.k2s(peak), law.k2);
      // The contact let go: no force, history gone.
      EXPECT_EQ(path.back().force, 0.0);
      EXPECT_EQ(MulticontactAdhesiveLaw::delta_max(
                  dem.pair_contacts()[0].history),
                0.0);
    }
}

TEST(MulticontactDynamics, PressureTermUsesLastStepsParticleStress)
{
  // F = F_Eq6 + beta nu pi R* delta P (Eq. 14, A = pi R* delta), with
  // P = -(p_i + p_j) and p_i = tr(sigma_i)/3 from the previous step:
  // for one contact sigma_i = -F l_i n (x) n / V_i, l_i = R_i - delta/2.
  const double R1 = 100e-6, R2 = 100e-6, beta = 1.3, nu = 0.3;
  const double r2 = 5.0, rc = 0.5, phi = 0.02;
  ExplicitDem  dem(law_material(r2, rc, phi, beta),
                  PeriodicCell::box(Eigen::Vector3d(1e-2, 1e-2, 1e-2),
                                    {true, true, false}));
  dem.add_particle(Eigen::Vector3d(5e-3, 5e-3, 5e-3), R1);
  dem.add_particle(Eigen::Vector3d(5e-3 + R1 + R2 + 1e-7, 5e-3, 5e-3), R2);
  const double   R = R1 * R2 / (R1 + R2);
  const PaperLaw law(R, effective_modulus(2.58e8, nu, 2.58e8, nu), r2, rc, phi);
  dem.set_fixed_time_step(1e-8);
  const auto path
    = drive(dem, {0.2 * law.delta_star, 0.05 * law.delta_star}, 0.05);
  const double V       = 4.0 / 3.0 * pi * R1 * R1 * R1;
  int          checked = 0;
  for (std::size_t k = 1; k < path.size(); ++k)
    {
      const auto &a = path[k - 1], &b = path[k];
      if (a.delta <= 0.0 || b.delta <= 0.0)
        continue;
      const double l = R1 - 0.5 * a.delta;
      const double P = 2.0 * a.force * l / (3.0 * V);
      const double expected
        = law.force(b.delta, b.delta_max) + beta * nu * pi * R * b.delta * P;
      EXPECT_NEAR(b.force, expected, 1e-9 * std::abs(expected) + 1e-15);
      ++checked;
    }
  EXPECT_GT(checked, 100);
  // The stress tensor of the last state: uniaxial along the contact normal.
  const auto &p = dem.particles();
  const auto &c = dem.pair_contacts()[0];
  ASSERT_GT(c.overlap, 0.0);
  const double l = R1 - 0.5 * c.overlap;
  EXPECT_NEAR(p.stress[0](0, 0),
              -c.normal_force * l / V,
              1e-9 * std::abs(c.normal_force * l / V));
  EXPECT_NEAR(p.stress[0](1, 1), 0.0, 1e-12 * std::abs(p.stress[0](0, 0)));
  EXPECT_NEAR(p.stress[0](0, 1), 0.0, 1e-12 * std::abs(p.stress[0](0, 0)));
  EXPECT_NEAR(p.pressure[1], p.stress[1].trace() / 3.0, 1e-12);
}

TEST(MulticontactDynamics, BetaZeroElasticLawIsConventionalHertz)
{
  // A compressed chain of three spheres: the middle one has two contacts
  // and a large particle pressure. With k2 = k1, kc = 0 and beta = 0 every
  // contact force is Hertz's whatever the pressure; with beta > 0 it is
  // larger by beta nu pi R* delta P.
  for (const double beta : {0.0, 1.5})
    {
      ExplicitDem  dem(law_material(1.0, 0.0, 0.0, beta),
                      PeriodicCell::box(Eigen::Vector3d(1e-2, 1e-2, 1e-2),
                                        {true, true, false}));
      const double R[3] = {100e-6, 70e-6, 90e-6};
      dem.add_particle(Eigen::Vector3d(5e-3, 5e-3, 5e-3), R[0]);
      dem.add_particle(Eigen::Vector3d(5e-3 + R[0] + R[1] - 4e-6, 5e-3, 5e-3),
                       R[1]);
      dem.add_particle(Eigen::Vector3d(5e-3 + R[0] + 2 * R[1] + R[2] - 7e-6,
                                       5e-3,
                                       5e-3),
                       R[2]);
      for (int i = 0; i < 3; ++i)
        dem.set_kinematic(i, true);
      dem.step();
      const std::vector<double> pressure = dem.particles().pressure;
      dem.step();
      ASSERT_EQ(dem.contact_count(), 2u);
      EXPECT_LT(pressure[1], 0.0);
      for (const auto &c : dem.pair_contacts())
        {
          const HertzLaw hertz
            = HertzLaw::for_pair(R[c.i], 2.58e8, 0.3, R[c.j], 2.58e8, 0.3);
          const double Reff     = R[c.i] * R[c.j] / (R[c.i] + R[c.j]);
          const double P        = -(pressure[c.i] + pressure[c.j]);
          const double expected = hertz.response(c.overlap).force
                                  + beta * 0.3 * pi * Reff * c.overlap * P;
          EXPECT_NEAR(c.normal_force, expected, 1e-10 * expected);
          if (beta > 0.0)
            {
              EXPECT_GT(c.normal_force, hertz.response(c.overlap).force);
            }
        }
    }
}

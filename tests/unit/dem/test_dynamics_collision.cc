// Binary collisions through the explicit DEM integrator against closed
// forms: Hertz's maximum overlap, energy conservation without damping,
// the coefficient of restitution of the Hertzian dashpot, and a sphere
// sliding into rolling on a plate (Coulomb friction, rolling torque).

#include "dem/contact/pair_properties.h"
#include "dem/dynamics/explicit_dem.h"
#include "dem/dynamics/restitution_damping.h"
#include "tests/support/binary_collision.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax::dem;

namespace
{

  using compax::testing::big_cell;
  using compax::testing::sphere_mass;

  DemMaterial
  elastic_material(const double restitution, const double friction = 0.0)
  {
    return compax::testing::collision_material(2.58e8,
                                               0.3,
                                               restitution,
                                               friction);
  }

  /// Runs a head-on collision along x; returns the relative speeds before
  /// and after, and the largest overlap.
  struct Collision
  {
    double v_before, v_after, delta_max, worst_energy_error;
  };

  Collision
  head_on(ExplicitDem &dem, const double speed, const bool track_energy)
  {
    auto &p       = dem.particles();
    p.velocity[0] = Eigen::Vector3d(speed, 0.0, 0.0);
    p.velocity[1] = Eigen::Vector3d(-speed, 0.0, 0.0);
    Collision    c{2.0 * speed, 0.0, 0.0, 0.0};
    const double e0      = dem.kinetic_energy();
    bool         touched = false;
    for (int step = 0; step < 2000000; ++step)
      {
        dem.step();
        const double gap
          = (p.position[1] - p.position[0]).norm() - p.radius[0] - p.radius[1];
        c.delta_max = std::max(c.delta_max, -gap);
        if (gap < 0.0)
          touched = true;
        if (track_energy)
          c.worst_energy_error = std::max(
            c.worst_energy_error,
            std::abs(dem.kinetic_energy() + dem.elastic_energy() - e0) / e0);
        if (touched && gap > 0.0)
          break;
      }
    c.v_after = (p.velocity[1] - p.velocity[0]).dot(Eigen::Vector3d::UnitX());
    return c;
  }
} // namespace

TEST(RestitutionDamping, NoDampingGivesElasticRebound)
{
  EXPECT_NEAR(hertz_restitution(0.0), 1.0, 1e-6);
  EXPECT_EQ(hertz_damping_ratio(1.0), 0.0);
}

TEST(RestitutionDamping, SmallDampingLosesEnergyAtTheLinearizedRate)
{
  // For a weak dashpot the energy lost is the dashpot work along the
  // undamped Hertz path: 1 - e^2 ~ 2 c int u^{1/4} u'^2 dt, c = 2
  // sqrt(3/2) zeta, with u'^2 = 1 - 4/5 u^{5/2} (energy conservation) and
  // dt = du/u': (1 - e^2)/2 ~ 2 c int_0^{u_m} u^{1/4} sqrt(1 - 4/5 u^{5/2})
  // du (both halves), u_m = (5/4)^{2/5}, so 1 - e ~ 2 c I. The integral I
  // by the midpoint rule.
  const double zeta = 1e-3, c = 2.0 * std::sqrt(1.5) * zeta;
  const double u_m = std::pow(1.25, 0.4);
  const int    n   = 200000;
  double       I   = 0.0;
  for (int k = 0; k < n; ++k)
    {
      const double u = (k + 0.5) * u_m / n;
      I += std::pow(u, 0.25)
           * std::sqrt(std::max(0.0, 1 - 0.8 * std::pow(u, 2.5))) * u_m / n;
    }
  const double loss = 1.0 - hertz_restitution(zeta);
  EXPECT_NEAR(loss, 2.0 * c * I, 0.01 * 2.0 * c * I);
}

TEST(ExplicitDemCollision, UndampedHeadOnReachesHertzOverlapAndConservesEnergy)
{
  const double R1 = 100e-6, R2 = 60e-6, v = 0.2;
  ExplicitDem  dem(elastic_material(1.0), big_cell());
  dem.add_particle(Eigen::Vector3d(4e-3, 5e-3, 5e-3), R1);
  dem.add_particle(Eigen::Vector3d(4e-3 + R1 + R2 + 1e-6, 5e-3, 5e-3), R2);
  const Collision c = head_on(dem, v, true);

  // Hertz: 1/2 m* v_rel^2 = 2/5 k delta_max^{5/2}, k = 4/3 E* sqrt(R*).
  const double m
    = 1.0 / (1.0 / sphere_mass(R1, 1541.1) + 1.0 / sphere_mass(R2, 1541.1));
  const double E  = 2.58e8 / (2.0 * (1.0 - 0.09));
  const double R  = R1 * R2 / (R1 + R2);
  const double k  = 4.0 / 3.0 * E * std::sqrt(R);
  const double dm = std::pow(1.25 * m * 4 * v * v / k, 0.4);
  EXPECT_NEAR(c.delta_max, dm, 2e-3 * dm);
  // Elastic, frictionless: kinetic + Hertz energy is conserved to the
  // integrator's accuracy, and the particles separate at the same speed.
  EXPECT_LT(c.worst_energy_error, 2e-3);
  EXPECT_NEAR(c.v_after, c.v_before, 1e-3 * c.v_before);
}

TEST(ExplicitDemCollision, ObliqueFrictionlessCollisionConservesEnergy)
{
  // Velocity Verlet's energy error is O(dt^2): 3.5e-3 at the default step
  // (0.2 dt_Rayleigh) for this fast collision, below 1e-3 at half of it.
  DynamicsSettings fine;
  fine.rayleigh_factor = 0.1;
  ExplicitDem  dem(elastic_material(1.0), big_cell(), fine);
  const double R = 80e-6;
  dem.add_particle(Eigen::Vector3d(4e-3, 5e-3, 5e-3), R);
  dem.add_particle(Eigen::Vector3d(4e-3 + 2.05 * R, 5e-3 + 0.9 * R, 5e-3), R);
  auto &p                  = dem.particles();
  p.velocity[0]            = Eigen::Vector3d(0.3, 0.0, 0.0);
  p.velocity[1]            = Eigen::Vector3d(-0.3, 0.0, 0.0);
  const double          e0 = dem.kinetic_energy();
  const Eigen::Vector3d P0
    = p.mass[0] * p.velocity[0] + p.mass[1] * p.velocity[1];
  double worst = 0.0;
  for (int step = 0; step < 20000; ++step)
    {
      dem.step();
      worst = std::max(
        worst, std::abs(dem.kinetic_energy() + dem.elastic_energy() - e0) / e0);
    }
  ASSERT_GT(dem.contact_count() + 1, 0u);
  EXPECT_LT(worst, 2e-3);
  // Separated again: all energy kinetic; momentum conserved; no spin.
  EXPECT_NEAR(dem.kinetic_energy(), e0, 1e-3 * e0);
  const Eigen::Vector3d P
    = p.mass[0] * p.velocity[0] + p.mass[1] * p.velocity[1];
  EXPECT_LT((P - P0).norm(), 1e-9 * p.mass[0] * 0.3);
  EXPECT_EQ(p.angular_velocity[0].norm(), 0.0);
  // The collision deflected the particles (it happened).
  EXPECT_GT(std::abs(p.velocity[0][1]), 0.01);
}

TEST(ExplicitDemCollision, RestitutionMatchesItsCoefficient)
{
  // The dashpot was inverted for e on the exact collision ODE, so the DEM
  // reproduces e up to its time discretization, first order here (the
  // dashpot uses the half-step velocity and delta^{1/4} is not smooth at
  // contact): within 3% at the default step (about 20 steps per contact
  // at 0.5 m/s), within 0.3% at a step 16 times finer.
  for (const double factor : {0.2, 0.0125})
    for (const double e : {0.352, 0.6, 0.9})
      for (const double v : {0.05, 0.5})
        {
          const double     R1 = 100e-6, R2 = 50e-6;
          DynamicsSettings settings;
          settings.rayleigh_factor = factor;
          ExplicitDem dem(elastic_material(e), big_cell(), settings);
          dem.add_particle(Eigen::Vector3d(4e-3, 5e-3, 5e-3), R1);
          dem.add_particle(Eigen::Vector3d(4e-3 + R1 + R2 + 1e-6, 5e-3, 5e-3),
                           R2);
          const Collision c = head_on(dem, v, false);
          EXPECT_NEAR(c.v_after / c.v_before,
                      e,
                      (factor > 0.1 ? 0.03 : 0.003) * e)
            << "e = " << e << ", v = " << v << ", dt factor " << factor;
        }
}

TEST(ExplicitDemCollision, PlateReboundMatchesWallRestitution)
{
  DemMaterial m               = elastic_material(1.0);
  m.particle_wall.restitution = 0.5;
  ExplicitDem  dem(m, big_cell());
  const double R = 100e-6;
  dem.add_particle(Eigen::Vector3d(5e-3, 5e-3, 1e-3 + R + 1e-7), R);
  dem.add_plates(1e-3, 9e-3);
  auto &p       = dem.particles();
  p.velocity[0] = Eigen::Vector3d(0.0, 0.0, -0.3);
  bool touched  = false;
  for (int step = 0; step < 100000; ++step)
    {
      dem.step();
      if (dem.wall_contact_count() > 0)
        touched = true;
      else if (touched)
        break;
    }
  EXPECT_NEAR(p.velocity[0][2], 0.5 * 0.3, 0.03 * 0.15);
}

TEST(ExplicitDemFriction,
     SlidingSphereStartsRollingAndDeceleratesByRollingTorque)
{
  // A sphere launched sliding on a plate under gravity: Coulomb friction
  // mu m g decelerates it (v = v0 - mu g t) and, less the rolling torque
  // mu_r R m g, spins it up (R omega = 2.5 (mu - mu_r) g t) until it rolls
  // at t_roll = v0 / (g (3.5 mu - 2.5 mu_r)); with mu_r = 0 that is the
  // classical 5/7 v0. Then the constant directional torque decelerates the
  // rolling sphere at mu_r g R^2 / (I/m + R^2) = mu_r g / 1.4.
  const double R = 1e-3, g = 9.81, v0 = 0.1, mu = 0.3, mu_r = 0.02;
  DemMaterial  m                   = elastic_material(0.3, mu);
  m.particle_wall.rolling_friction = mu_r;
  m.gravity                        = Eigen::Vector3d(0.0, 0.0, -g);
  ExplicitDem dem(m,
                  PeriodicCell::box(Eigen::Vector3d(1.0, 1.0, 1e-2),
                                    {true, true, false}));
  // Start at the Hertz equilibrium overlap (m g / k)^{2/3}.
  const double k
    = 4.0 / 3.0 * effective_modulus(2.58e8, 0.3, 7.62e10, 0.31) * std::sqrt(R);
  const double mass = sphere_mass(R, 1541.1);
  const double d_eq = std::pow(mass * g / k, 2.0 / 3.0);
  dem.add_particle(Eigen::Vector3d(0.5, 0.5, R - d_eq), R);
  dem.add_plates(0.0, 5e-3);
  auto &p       = dem.particles();
  p.velocity[0] = Eigen::Vector3d(v0, 0.0, 0.0);

  const double t_roll = v0 / (g * (3.5 * mu - 2.5 * mu_r));
  const double v_at   = v0 - mu * g * t_roll;
  while (dem.time() < 0.5 * t_roll)
    dem.step();
  // Sliding: v = v0 - mu g t.
  EXPECT_NEAR(p.velocity[0][0], v0 - mu * g * dem.time(), 0.01 * v0);
  while (dem.time() < 1.5 * t_roll)
    dem.step();
  const double v_roll = p.velocity[0][0];
  const double t1     = dem.time();
  // Rolling: v = R omega_y, from v_at less the rolling deceleration since.
  EXPECT_NEAR(v_roll, R * p.angular_velocity[0][1], 1e-3 * v0);
  EXPECT_NEAR(v_roll, v_at - mu_r * g / 1.4 * (t1 - t_roll), 0.01 * v0);
  while (dem.time() < t1 + 0.02)
    dem.step();
  const double a = (p.velocity[0][0] - v_roll) / (dem.time() - t1);
  EXPECT_NEAR(a, -mu_r * g / 1.4, 0.03 * mu_r * g / 1.4);
}

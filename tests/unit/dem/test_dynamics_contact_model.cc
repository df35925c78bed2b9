// The explicit DEM on the particle solvers' law interface (ContactModel):
// binary collisions against closed forms and energy balances of the law
// itself. Hertz: the largest overlap of Hertz's theory and an elastic
// rebound. Walton-Braun: the restitution sqrt(k1/k2) of a hysteretic
// linear spring, between spheres and against a plate. Bonded
// elasto-plastic law (Gonzalez 2018): the kinetic energy is spent on the
// loading branch up to the largest overlap, and what comes back is the
// work of the unloading branch at the largest overlap's internal
// variables, or, where that work is negative, the bridge holds the pair.

#include "dem/contact/contact_law_registry.h"
#include "dem/dynamics/explicit_dem.h"
#include "tests/support/binary_collision.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/walton_braun_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

namespace
{
  const double density = 1541.1;

  using compax::testing::big_cell;

  /// No dashpot, no friction: the contact law alone exchanges energy.
  DemMaterial
  undamped_material()
  {
    return compax::testing::collision_material(material1::E,
                                               material1::nu,
                                               1.0);
  }

  double
  sphere_mass(const double R)
  {
    return compax::testing::sphere_mass(R, density);
  }

  /// A head-on collision of two spheres of radius R along x at relative
  /// speed v; returns the largest overlap and the relative speed after.
  struct Collision
  {
    double delta_max = 0.0;
    double v_after   = 0.0;
    /// Whether the spheres parted beyond any bridge's reach (0.05 R).
    bool parted = false;
  };

  /// The spheres may be added with another radius @p added_as and grown
  /// (or shrunk) to R before the collision.
  Collision
  head_on(const ContactModel &model,
          const double        R,
          const double        v,
          const double        added_as = 0.0)
  {
    ExplicitDem  dem(undamped_material(), big_cell());
    const double R0 = added_as > 0.0 ? added_as : R;
    dem.use_contact_model(model);
    dem.add_particle(Eigen::Vector3d(4e-3, 5e-3, 5e-3), R0);
    dem.add_particle(Eigen::Vector3d(4e-3 + 2.0 * R + 1e-7, 5e-3, 5e-3), R0);
    dem.time_step(); // the neighbour list and the laws at radius R0
    dem.set_radius(0, R);
    dem.set_radius(1, R);
    auto &p       = dem.particles();
    p.velocity[0] = Eigen::Vector3d(0.5 * v, 0.0, 0.0);
    p.velocity[1] = Eigen::Vector3d(-0.5 * v, 0.0, 0.0);
    // About 2000 steps per contact: the integrator's error is small
    // against the tolerances below.
    dem.set_fixed_time_step(1e-9);
    Collision c;
    bool      touched = false;
    for (int step = 0; step < 200000; ++step)
      {
        dem.step();
        const double gap = (p.position[1] - p.position[0]).norm() - 2.0 * R;
        c.delta_max      = std::max(c.delta_max, -gap);
        touched          = touched || gap < 0.0;
        // Apart by more than any bridge reaches, or parting for good.
        c.parted = touched && gap > 0.05 * R;
        if (c.parted)
          break;
      }
    c.v_after = (p.velocity[1] - p.velocity[0]).x();
    return c;
  }

  /// Midpoint rule of f over [a, b].
  double
  integral(const std::function<double(double)> &f,
           const double                         a,
           const double                         b,
           const int                            n = 200000)
  {
    double sum = 0.0;
    for (int k = 0; k < n; ++k)
      sum += f(a + (k + 0.5) * (b - a) / n);
    return sum * (b - a) / n;
  }
} // namespace

TEST(ExplicitDemContactModel, HertzLawReachesHertzOverlapAndReboundsElastically)
{
  const RegisteredContactLaw *hertz = find_contact_law("hertz");
  ASSERT_NE(hertz, nullptr);
  ContactModel model(material1::elastoplastic(), 0.0);
  model.use_registered_law(*hertz, {});
  const double R = material1::R, v = 0.2;

  // 1/2 m* v^2 = 2/5 k delta_max^{5/2}, k = 4/3 E* sqrt(R/2); also for
  // spheres added at 0.9 R (already neighbours) and grown to R, whose laws
  // must follow the radius.
  const double m = 0.5 * sphere_mass(R);
  const double E = material1::E / (2.0 * (1.0 - material1::nu * material1::nu));
  const double k = 4.0 / 3.0 * E * std::sqrt(0.5 * R);
  const double dm = std::pow(1.25 * m * v * v / k, 0.4);
  for (const double added_as : {R, 0.9 * R})
    {
      const Collision c = head_on(model, R, v, added_as);
      EXPECT_NEAR(c.delta_max, dm, 2e-3 * dm) << "added as " << added_as;
      EXPECT_NEAR(c.v_after, v, 1e-3 * v) << "added as " << added_as;
    }
}

TEST(ExplicitDemContactModel, WaltonBraunRestitutionIsRootOfStiffnessRatio)
{
  // Plasticity depth 0: every un/reloading branch has k2 = k2_max.
  const double       ratio = 4.0;
  const ContactModel model = compax::testing::walton_braun_model(ratio, 0.0);
  const double       k1
    = find_contact_law("walton-braun")->parameters.front().default_value;
  const double R = material1::R, v = 0.2;

  // Two spheres: delta_max = v sqrt(m*/k1), e = sqrt(k1/k2).
  const Collision c      = head_on(model, R, v);
  const double    m_pair = 0.5 * sphere_mass(R);
  EXPECT_NEAR(c.delta_max, v * std::sqrt(m_pair / k1), 2e-3 * c.delta_max);
  EXPECT_NEAR(c.v_after / v, 1.0 / std::sqrt(ratio), 2e-3);

  // A sphere against the bottom plate, the plate's law of the model.
  ExplicitDem dem(undamped_material(), big_cell());
  dem.use_contact_model(model);
  dem.add_plates(0.0, 1e-2);
  dem.add_particle(Eigen::Vector3d(5e-3, 5e-3, R + 1e-7), R);
  dem.set_fixed_time_step(1e-9);
  dem.particles().velocity[0] = Eigen::Vector3d(0.0, 0.0, -v);
  double delta_max            = 0.0;
  for (int step = 0; step < 2000000; ++step)
    {
      dem.step();
      const double gap = dem.particles().position[0].z() - R;
      delta_max        = std::max(delta_max, -gap);
      if (delta_max > 0.0 && gap > 0.0)
        break;
    }
  EXPECT_NEAR(delta_max, v * std::sqrt(sphere_mass(R) / k1), 2e-3 * delta_max);
  EXPECT_NEAR(dem.particles().velocity[0].z() / v,
              1.0 / std::sqrt(ratio),
              2e-3);
}

TEST(ExplicitDemContactModel, BondedCollisionSpendsAndReturnsTheLawsWork)
{
  const double R = material1::R, m = 0.5 * sphere_mass(R);
  struct Case
  {
    double toughness, speed;
  };
  for (const Case run :
       {Case{0.0, 0.5}, Case{material1::K_Ic, 0.5}, Case{material1::K_Ic, 5.0}})
    {
      const ContactModel model(material1::elastoplastic(), run.toughness);
      const ParticleLaw  law = model.pair_law(0, R, 0, R);
      const double       v   = run.speed;
      const Collision    c   = head_on(model, R, v);
      SCOPED_TRACE("K_Ic = " + std::to_string(run.toughness)
                   + ", v = " + std::to_string(v));

      // Loading from a virgin contact: 1/2 m* v^2 = int_0^dm P(s) ds.
      const double loading_work = integral(
        [&](const double s) {
          return law_response(law, s, ContactHistory{}).force;
        },
        0.0,
        c.delta_max);
      EXPECT_NEAR(loading_work, 0.5 * m * v * v, 5e-3 * 0.5 * m * v * v);

      // Unloading at the internal variables of the largest overlap, down to
      // where the contact (or its bridge) parts: the work returned is
      // 1/2 m* v_after^2 if it is positive; if not, the bridge holds.
      const ContactHistory peak
        = updated_history(law, c.delta_max, ContactHistory{});
      const double returned = integral(
        [&](const double s) { return law_response(law, s, peak).force; },
        -0.05 * R,
        c.delta_max);
      EXPECT_EQ(c.parted, returned > 0.0);
      if (c.parted)
        {
          EXPECT_NEAR(0.5 * m * c.v_after * c.v_after,
                      returned,
                      1e-2 * returned);
        }
    }
}

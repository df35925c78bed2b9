// Adhesive elasto-plastic multi-contact law of Giannis et al. 2021. The
// corrected branch constants are checked against branch crossings solved by
// bisection here, from the stated physics only: the un/reloading branch of
// slope k2* (in x = delta^{3/2}) leaves the loading branch k1 x at
// delta_max, has zero force at delta_0 and meets -kc x at delta_min.

#include "dem/contact/hertz.h"
#include "dem/contact/multicontact_adhesive.h"
#include "dem/contact/pair_properties.h"
#include "dem/numbers.h"
#include "elastic_sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace
{
  using namespace compax::dem;

  using namespace compax::dem::contact_test;

  // MCC-A and MCC-P moduli of Table 2, two radii; the rigid flat is rigid_flat.
  const ElasticSphere particle_a{100e-6, 2.58e8, 0.30};
  const ElasticSphere particle_b{150e-6, 1.34e9, 0.30};

  MulticontactAdhesiveLaw::Parameters
  table3()
  {
    MulticontactAdhesiveLaw::Parameters p;
    p.unloading_stiffness_ratio = 120;
    p.adhesion_stiffness_ratio  = 0.5;
    p.plasticity_depth          = 0.99;
    p.multicontact_prefactor    = 1.3;
    p.pull_off_force            = 0.0;
    p.poisson_ratio             = 0.3;
    return p;
  }

  MulticontactAdhesiveLaw
  make_law(const ElasticSphere                       &m2,
           const MulticontactAdhesiveLaw::Parameters &p = table3())
  {
    return MulticontactAdhesiveLaw::for_pair(
      particle_a.R, particle_a.E, particle_a.nu, m2.R, m2.E, m2.nu, p);
  }

  double
  reduced_radius(const ElasticSphere &m2)
  {
    return particle_a.R * m2.R / (particle_a.R + m2.R);
  }

  double
  reduced_radius_wall()
  {
    return particle_a.R;
  }

  // k1 = 4/3 E sqrt(R), E with the inverse.
  double
  k1_of(const ElasticSphere &m2)
  {
    const double E
      = 1.0
        / ((1 - particle_a.nu * particle_a.nu) / particle_a.E
           + (std::isinf(m2.E) ? 0.0 : (1 - m2.nu * m2.nu) / m2.E));
    const double R
      = std::isinf(m2.R) ? reduced_radius_wall() : reduced_radius(m2);
    return 4.0 / 3.0 * E * std::sqrt(R);
  }

  // Eq. (11) read as an interpolation between k1 and k2 (Fig. 3), with
  // delta*_max of Eq. (12) (2 Ri Rj/(Ri+Rj); 2 Ri for a rigid_flat).
  double
  k2_star(const ElasticSphere                       &m2,
          const MulticontactAdhesiveLaw::Parameters &p,
          double                                     delta_max)
  {
    const double k1    = k1_of(m2);
    const double k2    = p.unloading_stiffness_ratio * k1;
    const double two_R = std::isinf(m2.R)
                           ? 2 * particle_a.R
                           : 2 * particle_a.R * m2.R / (particle_a.R + m2.R);
    const double limit = k2 / (k2 - k1) * p.plasticity_depth * two_R;
    const double w     = std::min(delta_max / limit, 1.0);
    return (1 - w) * k1 + w * k2;
  }

  double
  bisect(const std::function<double(double)> &f, double lo, double hi)
  {
    double flo = f(lo);
    for (int i = 0; i < 200; ++i)
      {
        const double mid  = 0.5 * (lo + hi);
        const double fmid = f(mid);
        if ((fmid > 0) == (flo > 0))
          {
            lo  = mid;
            flo = fmid;
          }
        else
          hi = mid;
      }
    return 0.5 * (lo + hi);
  }

  double
  x_of(double d)
  {
    return d * std::sqrt(d);
  }

  ContactHistory
  history_with_max(double delta_max)
  {
    ContactHistory h;
    h[MulticontactAdhesiveLaw::delta_max_slot] = delta_max;
    return h;
  }

  /// The un/reloading branch of particle_a's law with a partner for one
  /// delta_max: it leaves the loading branch k1 x at delta_max with slope
  /// k2* (x = delta^{3/2}).
  struct UnloadingBranch
  {
    const MulticontactAdhesiveLaw &law;
    double                         k1, delta_max, k2_star;

    /// The branch's force at overlap d.
    double
    force(const double d) const
    {
      return k1 * x_of(delta_max) + k2_star * (x_of(d) - x_of(delta_max));
    }
  };

  /// Calls @p check with the branch of particle_a's single-contact law
  /// (parameters @p p without the multi-contact term) with particle_b and
  /// with the rigid_flat, at each delta_max of @p fractions times the reduced
  /// radius.
  void
  for_each_unloading_branch(
    MulticontactAdhesiveLaw::Parameters                 p,
    const std::initializer_list<double>                 fractions,
    const std::function<void(const UnloadingBranch &)> &check)
  {
    p.multicontact_prefactor = 0;
    for (const ElasticSphere &m2 : {particle_b, rigid_flat})
      {
        const MulticontactAdhesiveLaw law = make_law(m2, p);
        const double                  R
          = std::isinf(m2.R) ? reduced_radius_wall() : reduced_radius(m2);
        const double k1 = k1_of(m2);
        for (const double fraction : fractions)
          {
            const double dmax = fraction * R;
            check(UnloadingBranch{law, k1, dmax, k2_star(m2, p, dmax)});
          }
      }
  }

  TEST(MulticontactAdhesive, LoadingStiffnessUsesInverseEffectiveModulus)
  {
    for (const ElasticSphere &m2 : {particle_b, rigid_flat})
      {
        const MulticontactAdhesiveLaw law = make_law(m2);
        EXPECT_NEAR(law.loading_stiffness(), k1_of(m2), 1e-13 * k1_of(m2));
        EXPECT_EQ(law.name(), "multicontact-adhesive");
      }
  }

  TEST(MulticontactAdhesive, PlasticOverlapIsZeroForceCrossing)
  {
    auto p = table3();
    // phi_f = 0.99 (k2* interpolates) and 0.005 (k2* = k2).
    for (const double phi : {0.99, 0.005})
      {
        p.plasticity_depth = phi;
        for_each_unloading_branch(
          p, {0.002, 0.05, 0.2}, [](const UnloadingBranch &b) {
            EXPECT_NEAR(b.law.unloading_stiffness(b.delta_max),
                        b.k2_star,
                        1e-12 * b.k2_star);
            // Unloading line through (x_max, k1 x_max) crosses zero.
            const double d0
              = bisect([&](double d) { return b.force(d); }, 0.0, b.delta_max);
            EXPECT_NEAR(b.law.plastic_overlap(b.delta_max),
                        d0,
                        1e-12 * b.delta_max);
            // The law's own force vanishes there.
            const double F
              = b.law.evaluate(d0, history_with_max(b.delta_max)).force;
            EXPECT_NEAR(F, 0.0, 1e-9 * b.k1 * x_of(b.delta_max));
          });
      }
  }

  TEST(MulticontactAdhesive, UnloadingSlopeIsInterpolatedK2Star)
  {
    auto p                            = table3();
    p.multicontact_prefactor          = 0;
    const ElasticSphere          &m2  = particle_b;
    const MulticontactAdhesiveLaw law = make_law(m2, p);
    const double                  R   = reduced_radius(m2);
    const double                  k1  = k1_of(m2);
    const double                  k2  = 120 * k1;
    for (const double dmax : {0.001 * R, 0.03 * R, 0.5 * R, 3.0 * R})
      {
        // Slope in x of the law's unloading forces, from the forces alone.
        const ContactHistory h  = history_with_max(dmax);
        const double         d1 = 0.9995 * dmax;
        const double         slope
          = (law.evaluate(dmax, h).force - law.evaluate(d1, h).force)
            / (x_of(dmax) - x_of(d1));
        const double k2s = k2_star(m2, p, dmax);
        EXPECT_NEAR(slope, k2s, 1e-8 * k2s);
        // Between k1 and k2 (the printed Eq. 11 exceeds k2 here).
        EXPECT_GE(slope, k1 * (1 - 1e-9));
        EXPECT_LE(slope, k2 * (1 + 1e-9));
      }
    // Continuous at delta*_max, k2 beyond.
    const double limit = law.plastic_flow_limit();
    EXPECT_NEAR(limit, 120.0 / 119.0 * 0.99 * 2 * R, 1e-12 * R);
    EXPECT_NEAR(law.unloading_stiffness(limit * (1 - 1e-12)), k2, 1e-9 * k2);
    EXPECT_EQ(law.unloading_stiffness(limit * 1.5), k2);
  }

  TEST(MulticontactAdhesive, MinimumOverlapMeetsAdhesiveBranch)
  {
    auto p = table3();
    for (const double kc : {0.5, 3.0})
      {
        p.adhesion_stiffness_ratio = kc;
        for_each_unloading_branch(
          p, {0.01, 0.1, 2.0}, [kc](const UnloadingBranch &b) {
            const MulticontactAdhesiveLaw &law  = b.law;
            const double                   k1   = b.k1;
            const double                   dmax = b.delta_max;
            const auto                     meet
              = [&](double d) { return b.force(d) + kc * k1 * x_of(d); };
            const double dmin = bisect(meet, 0.0, dmax);
            EXPECT_NEAR(law.minimum_overlap(dmax), dmin, 1e-12 * dmax);
            // Eq. (8).
            const double Fmin = -kc * k1 * x_of(dmin);
            EXPECT_NEAR(law.minimum_force(dmax), Fmin, 1e-10 * std::abs(Fmin));
            EXPECT_NEAR(law.evaluate(dmin, history_with_max(dmax)).force,
                        Fmin,
                        1e-9 * std::abs(Fmin));
            // Below delta_min the adhesive branch.
            const double d = 0.5 * dmin;
            EXPECT_NEAR(law.evaluate(d, history_with_max(dmax)).force,
                        -kc * k1 * x_of(d),
                        1e-12 * kc * k1 * x_of(d));
          });
      }
  }

  // A load-unload-reload path through every branch.
  std::vector<double>
  path(double R)
  {
    std::vector<double> d;
    for (int i = 1; i <= 60; ++i) // load to 0.06 R
      d.push_back(0.001 * R * i);
    for (int i = 59; i >= 3; --i) // unload through the adhesive branch
      d.push_back(0.001 * R * i);
    for (int i = 4; i <= 90; ++i) // reload past the old maximum
      d.push_back(0.001 * R * i);
    for (int i = 89; i >= 40; --i) // unload again
      d.push_back(0.001 * R * i);
    return d;
  }

  TEST(MulticontactAdhesive, ReducesToHertz)
  {
    // k2 = k1, no adhesion and no multi-contact term (Table 3's nu).
    auto p                      = table3();
    p.unloading_stiffness_ratio = 1;
    p.adhesion_stiffness_ratio  = 0;
    p.plasticity_depth          = 0.5;
    p.multicontact_prefactor    = 0;
    for (const ElasticSphere &m2 : {particle_b, rigid_flat})
      {
        const MulticontactAdhesiveLaw law   = make_law(m2, p);
        const HertzLaw                hertz = HertzLaw::for_pair(
          particle_a.R, particle_a.E, particle_a.nu, m2.R, m2.E, m2.nu);
        ContactHistory h;
        for (const double d : path(law.effective_radius()))
          {
            const ContactResponse r = law.evaluate(d, h);
            const ContactResponse e = hertz.evaluate(d, {});
            EXPECT_NEAR(r.force, e.force, 1e-13 * e.force);
            EXPECT_NEAR(r.stiffness, e.stiffness, 1e-13 * e.stiffness);
            EXPECT_NEAR(r.contact_radius,
                        e.contact_radius,
                        1e-13 * e.contact_radius);
            h = law.updated_history(d, h);
          }
        EXPECT_EQ(law.evaluate(-1e-9, h).force, 0.0);
      }
  }

  TEST(MulticontactAdhesive, ForceContinuousAcrossBranchSwitches)
  {
    auto p           = table3();
    p.pull_off_force = -1e-4;
    for (const ElasticSphere &m2 : {particle_b, rigid_flat})
      {
        const MulticontactAdhesiveLaw law = make_law(m2, p);
        const double                  R   = law.effective_radius();
        ContactContext                context;
        context.particle_pressure = -2e6;
        for (const double dmax : {0.02 * R, 0.3 * R, 2.5 * R})
          {
            const ContactHistory h     = history_with_max(dmax);
            const double         scale = law.evaluate(dmax, h, context).force;
            for (const double kink :
                 {dmax, law.minimum_overlap(dmax), law.plastic_overlap(dmax)})
              {
                const double eta = 1e-10 * kink;
                const double jump
                  = law.evaluate(kink + eta, h, context).force
                    - law.evaluate(kink - eta, h, context).force;
                // No more than the steepest branch (k2, plus the
                // multi-contact slope) can climb over 2 eta.
                const double steepest = 1.5 * 120 * k1_of(m2) * std::sqrt(kink)
                                        + 1.3 * 0.3 * pi * R * 2e6;
                EXPECT_LT(std::abs(jump), 2.2 * eta * steepest + 1e-13 * scale)
                  << "kink " << kink;
              }
          }
      }
  }

  TEST(MulticontactAdhesive, StiffnessIsCentralDifferenceAlongHistory)
  {
    auto p           = table3();
    p.pull_off_force = -2e-4;
    for (const ElasticSphere &m2 : {particle_b, rigid_flat})
      for (const double pressure : {-3e6, 1e6})
        {
          const MulticontactAdhesiveLaw law = make_law(m2, p);
          ContactContext                context;
          context.particle_pressure = pressure;
          ContactHistory h;
          int            checked = 0;
          for (const double base : path(law.effective_radius()))
            {
              // Off the grid points, away from the kinks.
              const double d    = base * (1 + 3.7e-4);
              const double step = 1e-6 * d;
              const double dmin
                = law.minimum_overlap(MulticontactAdhesiveLaw::delta_max(h));
              if (std::abs(d - MulticontactAdhesiveLaw::delta_max(h))
                    < 100 * step
                  || std::abs(d - dmin) < 100 * step)
                continue;
              const ContactResponse r = law.evaluate(d, h, context);
              const double fd = (law.evaluate(d + step, h, context).force
                                 - law.evaluate(d - step, h, context).force)
                                / (2 * step);
              EXPECT_NEAR(r.stiffness, fd, 1e-6 * std::abs(r.stiffness))
                << "delta = " << d
                << ", delta_max = " << MulticontactAdhesiveLaw::delta_max(h);
              ++checked;
              h = law.updated_history(d, h, context);
            }
          EXPECT_GT(checked, 200);
        }
  }

  TEST(MulticontactAdhesive, MulticontactTermIsBetaNuAreaPressure)
  {
    auto p                             = table3();
    auto p0                            = p;
    p0.multicontact_prefactor          = 0;
    const MulticontactAdhesiveLaw law  = make_law(particle_b, p);
    const MulticontactAdhesiveLaw law0 = make_law(particle_b, p0);
    const double                  R    = reduced_radius(particle_b);
    ContactContext                context;
    context.particle_pressure = -5e6; // compressive mean stress
    for (const double d : {0.01 * R, 0.1 * R})
      for (const double dmax : {0.0, 0.5 * d, 2 * d})
        {
          const ContactHistory h     = history_with_max(dmax);
          const double         extra = law.evaluate(d, h, context).force
                               - law0.evaluate(d, h, context).force;
          // A = pi a^2 with a^2 = R delta; pressure positive in compression.
          const double expected = 1.3 * 0.3 * pi * R * d * 5e6;
          EXPECT_NEAR(extra, expected, 1e-10 * expected);
          EXPECT_GT(extra, 0.0);
        }
  }

  TEST(MulticontactAdhesive, HistoryChangesOnlyInUpdatedHistory)
  {
    const MulticontactAdhesiveLaw law = make_law(particle_b);
    ContactHistory                h   = MulticontactAdhesiveLaw::history(3e-6);
    h[1]                              = 2e-6; // a slot the law does not declare
    const ContactHistory  copy        = h;
    const ContactResponse first       = law.evaluate(2e-6, h);
    // Trial states beyond delta_max leave no trace.
    law.evaluate(9e-6, h);
    law.evaluate(1e-7, h);
    EXPECT_EQ(h, copy);
    const ContactResponse again = law.evaluate(2e-6, h);
    EXPECT_EQ(first.force, again.force);
    EXPECT_EQ(first.stiffness, again.stiffness);

    const ContactHistory up = law.updated_history(5e-6, h);
    EXPECT_EQ(MulticontactAdhesiveLaw::delta_max(up), 5e-6);
    EXPECT_EQ(up[1], h[1]);
    EXPECT_EQ(law.updated_history(1e-6, h), h);
  }

  TEST(MulticontactAdhesive, RejectsInvalidParameters)
  {
    auto p                      = table3();
    p.unloading_stiffness_ratio = 0.5;
    EXPECT_THROW(make_law(particle_b, p), std::invalid_argument);
    p                          = table3();
    p.adhesion_stiffness_ratio = -1;
    EXPECT_THROW(make_law(particle_b, p), std::invalid_argument);
  }
} // namespace

#include "dem/solver/fire_relaxation.h"
#include "dem/solver/lbfgs_relaxation.h"
#include "dem/solver/least_squares_trust_region.h"
#include "dem/solver/load_stepper.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/pressed_lattice.h"
#include "tests/support/sphere_column.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <vector>

using namespace compax::dem;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  // Material 1 of Gonzalez 2018, Table 1.
  using compax::testing::material1::E;
  using compax::testing::material1::kappa;
  using compax::testing::material1::m;
  using compax::testing::material1::nu;
  using compax::testing::material1::R;

  /// Plastic loading written out from Gonzalez 2018 Sec. 2-3, independently
  /// of compax: P = n_p a^{2+1/m}, a^2 = 2 c^2 R* gamma,
  /// n_p = pi k_m R*^{-1/m} kappa*, k_m = 3 6^{-1/m}, c^2 = 1.43 e^{-0.97/m}.
  struct PlasticLaw
  {
    double R_eff, kappa_eff;
    double
    force(double gamma) const
    {
      const double c2  = 1.43 * std::exp(-0.97 / m);
      const double n_p = pi * 3.0 * std::pow(6.0, -1.0 / m)
                         * std::pow(R_eff, -1.0 / m) * kappa_eff;
      const double a = std::sqrt(2.0 * c2 * R_eff * gamma);
      return n_p * std::pow(a, 2.0 + 1.0 / m);
    }
    double
    overlap(double P) const // inverse of force()
    {
      double lo = 0.0, hi = R;
      for (int i = 0; i < 200; ++i)
        (force(0.5 * (lo + hi)) < P ? lo : hi) = 0.5 * (lo + hi);
      return 0.5 * (lo + hi);
    }
  };
  const PlasticLaw sphere_flat{R, kappa};
  const PlasticLaw sphere_sphere{R / 2, kappa *std::pow(2.0, -1.0 / m)};

  double
  net_force_check(Bed &bed, const ContactModel &model, ContactSums &sums)
  {
    ContactAssembler a;
    Eigen::VectorXd  F;
    sums = a.residual(bed, model, F);
    return max_particle_norm(F) / sums.mean_force;
  }

  const Eigen::Vector3d column_rattler = compax::testing::column_rattler(R);

  /// The column of compax::testing::sphere_column() with Material 1's R.
  Bed
  column_with_rattler(const int N, const double squeeze)
  {
    return compax::testing::sphere_column(N, R, squeeze);
  }

  /// The one force P through the N + 1 contacts in series of a column
  /// squeezed by @p total: 2 gamma_sf(P) + (N-1) gamma_ss(P) = total
  /// (bisection).
  double
  column_force(const int N, const double total)
  {
    double lo = 0.0, hi = sphere_flat.force(total);
    for (int i = 0; i < 200; ++i)
      {
        const double P = 0.5 * (lo + hi);
        (2 * sphere_flat.overlap(P) + (N - 1) * sphere_sphere.overlap(P) < total
           ? lo
           : hi)
          = P;
      }
    return 0.5 * (lo + hi);
  }

  /// The column of column_with_rattler(N, total) solved at fixed (virgin)
  /// internal variables: balanced to @p tolerance, the punches carry
  /// column_force(N, total), the bottom sphere sits on its sphere-flat
  /// overlap, and the rattler, without a contact, has not moved.
  void
  expect_column_closed_form(Bed                &bed,
                            const ContactModel &model,
                            const int           N,
                            const double        total,
                            const double        tolerance)
  {
    const double P = column_force(N, total);
    ContactSums  sums;
    EXPECT_LT(net_force_check(bed, model, sums), tolerance);
    EXPECT_NEAR(sums.wall_force[int(Wall::upper_punch)], P, 1e-7 * P);
    EXPECT_NEAR(sums.wall_force[int(Wall::lower_punch)], P, 1e-7 * P);
    EXPECT_NEAR(bed.particles.positions[0][2],
                R - sphere_flat.overlap(P),
                1e-8 * R);
    EXPECT_EQ(bed.particles.positions[N], column_rattler);
  }
} // namespace

/// One sphere between two punches: two identical sphere-flat contacts in
/// series, each with overlap delta/2; then elastic unloading along Eq. (4)
/// without a bridge (no bonding with walls by default).
TEST(SolverEquilibrium, SphereBetweenPunches)
{
  const ContactModel model = compax::testing::material1::contact_model();
  Bed                bed;
  bed.walls.diameter    = 10 * R;
  bed.walls.upper_punch = 2 * R;
  bed.contacts.set_skin(0.3 * R);
  bed.particles.add({0.3 * R, 0.1 * R, 0.8 * R}, R);
  LoadStepper stepper(model);

  const double delta = 0.1 * R;
  DieWalls     w     = bed.walls;
  w.upper_punch      = 2 * R - delta;
  ASSERT_TRUE(stepper.advance(bed, w).converged);
  ContactSums sums;
  EXPECT_LT(net_force_check(bed, model, sums), 1e-6);
  const double P = sphere_flat.force(delta / 2);
  EXPECT_NEAR(sums.wall_force[int(Wall::upper_punch)], P, 1e-8 * P);
  EXPECT_NEAR(sums.wall_force[int(Wall::lower_punch)], P, 1e-8 * P);
  EXPECT_NEAR(bed.particles.positions[0][2], R - delta / 2, 1e-9 * R);

  // Unload by delta_u: each contact recovers delta_u / 2 elastically,
  // P = 2 n_p/pi a_p^{2+1/m} (asin x - x sqrt(1-x^2)), x = a/a_p,
  // a^2 = a_p^2 - (4 E* (gamma_p - gamma)/(3 n_p a_p^{1/m}))^2, E* of a
  // sphere on a rigid flat E/(1-nu^2).
  const double c2 = 1.43 * std::exp(-0.97 / m);
  const double n_p
    = pi * 3.0 * std::pow(6.0, -1.0 / m) * std::pow(R, -1.0 / m) * kappa;
  const double a_p   = std::sqrt(2 * c2 * R * delta / 2);
  const double E_eff = E / (1 - nu * nu);
  const double du    = 0.2 * 3 * n_p * std::pow(a_p, 1 + 1 / m) / (4 * E_eff);
  w.upper_punch += 2 * du;
  ASSERT_TRUE(stepper.advance(bed, w).converged);
  net_force_check(bed, model, sums);
  const double rec = 4 * E_eff * du / (3 * n_p * std::pow(a_p, 1 / m));
  const double x   = std::sqrt(a_p * a_p - rec * rec) / a_p;
  const double Pu  = 2 * n_p / pi * std::pow(a_p, 2 + 1 / m)
                    * (std::asin(x) - x * std::sqrt(1 - x * x));
  EXPECT_NEAR(sums.wall_force[int(Wall::upper_punch)], Pu, 1e-7 * P);
  EXPECT_NEAR(sums.wall_force[int(Wall::lower_punch)], Pu, 1e-7 * P);
}

/// Two spheres side by side across a die narrower than 4R: die wall -
/// sphere - sphere - die wall in series, 2 gamma_w + gamma_pp = 4R - D with
/// equal forces; the punches squeeze each sphere by gamma_z, which keeps
/// them from sliding past each other and does not act horizontally.
TEST(SolverEquilibrium, SpheresPressedAgainstDieWall)
{
  const ContactModel model = compax::testing::material1::contact_model();
  Bed                bed;
  const double       total = 0.08 * R, gamma_z = 0.02 * R;
  bed.walls.diameter    = 4 * R - total;
  bed.walls.upper_punch = 2 * R - 2 * gamma_z;
  bed.contacts.set_skin(0.3 * R);
  bed.particles.add({-R + 0.03 * R, 0.0, R}, R);
  bed.particles.add({R, 0.01 * R, R - 0.01 * R}, R);
  LoadStepper stepper(model);
  ASSERT_TRUE(stepper.equilibrate(bed).converged);

  // Series solution by bisection on the common force.
  double lo = 0.0, hi = sphere_flat.force(total);
  for (int i = 0; i < 200; ++i)
    {
      const double P = 0.5 * (lo + hi);
      (2 * sphere_flat.overlap(P) + sphere_sphere.overlap(P) < total ? lo : hi)
        = P;
    }
  const double P = 0.5 * (lo + hi);
  ContactSums  sums;
  EXPECT_LT(net_force_check(bed, model, sums), 1e-6);
  EXPECT_NEAR(sums.wall_force[int(Wall::die)], 2 * P, 1e-7 * P);
  const double Pz = sphere_flat.force(gamma_z);
  EXPECT_NEAR(sums.wall_force[int(Wall::upper_punch)], 2 * Pz, 1e-7 * Pz);
  EXPECT_NEAR(sums.wall_force[int(Wall::lower_punch)], 2 * Pz, 1e-7 * Pz);
  const double d
    = (bed.particles.positions[0] - bed.particles.positions[1]).norm();
  EXPECT_NEAR(d, 2 * R - sphere_sphere.overlap(P), 1e-9 * R);
}

/// A simple-cubic column of N spheres between the punches: N + 1 contacts
/// carry the same force, 2 sphere-flat contacts with gamma_w and N - 1
/// sphere-sphere contacts with gamma_pp, 2 gamma_w + (N-1) gamma_pp equal
/// to the punch displacement. (The two laws differ, so the overlaps are not
/// all the same; with equal laws they would be displacement / (N + 1).)
/// A rattler sits in the die away from the column and must not disturb
/// the solver.
TEST(SolverEquilibrium, SimpleCubicColumnAndRattler)
{
  const ContactModel model = compax::testing::material1::contact_model();
  const int          N     = 6;
  Bed                bed   = column_with_rattler(N, 0.0);
  LoadStepper        stepper(model);

  for (const double total : {0.05 * R, 0.2 * R, 0.5 * R})
    {
      DieWalls w    = bed.walls;
      w.upper_punch = 2 * R * N - total;
      const auto r  = stepper.advance(bed, w);
      ASSERT_TRUE(r.converged);
      const double P = column_force(N, total);
      ContactSums  sums;
      EXPECT_LT(net_force_check(bed, model, sums), 1e-6);
      EXPECT_NEAR(sums.wall_force[int(Wall::upper_punch)], P, 1e-7 * P);
      EXPECT_NEAR(sums.wall_force[int(Wall::lower_punch)], P, 1e-7 * P);
      EXPECT_NEAR(bed.particles.positions[0][2],
                  R - sphere_flat.overlap(P),
                  1e-9 * R);
      // The rattler carries no force and keeps where the affine predictor
      // of the punch motion put it.
      const Eigen::Vector3d moved(column_rattler[0],
                                  column_rattler[1],
                                  column_rattler[2] * w.height() / (2 * R * N));
      EXPECT_LT((bed.particles.positions[N] - moved).norm(), 1e-12 * R);
    }
}

/// L-BFGS at fixed (virgin) internal variables relaxes a column of spheres
/// squeezed between punches to the closed form: one force P through every
/// contact in series, 2 gamma_sf(P) + (N-1) gamma_ss(P) = total squeeze,
/// each contact on the plastic loading curve; the rattler beside the
/// column, without a contact, does not move. The column starts
/// unrelaxed: the whole squeeze sits in the top contact.
TEST(SolverEquilibrium, LbfgsRelaxesAColumnToTheClosedForm)
{
  const ContactModel model = compax::testing::material1::contact_model();
  const int          N     = 6;
  const double       total = 0.2 * R;
  Bed                bed   = column_with_rattler(N, total);

  LbfgsRelaxation  lbfgs;
  const double     tolerance = 1e-9;
  const FireResult r         = lbfgs.relax(bed, model, tolerance, 100000);
  ASSERT_TRUE(r.converged) << r.iterations << " evaluations, residual "
                           << r.relative_residual;
  expect_column_closed_form(bed, model, N, total, tolerance);
}

namespace
{
  /// Relaxes a bed large enough for the threaded residual, vector updates
  /// and Verlet search (2744 jittered spheres of a pressed simple cubic
  /// lattice, which comes apart to a force-free state) by @p evaluations
  /// residual evaluations of a fresh Minimiser on one, two and three
  /// threads, and expects the same positions to the bit and a lower
  /// largest net force.
  template <typename Minimiser>
  void
  expect_the_same_path_on_any_number_of_threads(const int evaluations)
  {
    const ContactModel model = compax::testing::material1::contact_model();
    const int          threads_before = omp_get_max_threads();
    const auto         largest_force  = [&](Bed &bed) {
      ContactAssembler assembler;
      Eigen::VectorXd  F;
      assembler.residual(bed, model, F);
      return max_particle_norm(F);
    };
    std::vector<Bed> relaxed;
    for (const int threads : {1, 2, 3})
      {
        omp_set_num_threads(threads);
        Bed              bed = compax::testing::pressed_lattice(model, R, 14);
        const double     before = largest_force(bed);
        Minimiser        minimiser;
        const FireResult r = minimiser.relax(bed, model, 1e-9, evaluations);
        EXPECT_EQ(r.iterations, evaluations) << threads << " threads";
        EXPECT_LT(largest_force(bed), 0.5 * before) << threads << " threads";
        relaxed.push_back(std::move(bed));
      }
    omp_set_num_threads(threads_before);
    for (std::size_t t = 1; t < relaxed.size(); ++t)
      for (std::size_t i = 0; i < relaxed[0].particles.size(); ++i)
        ASSERT_EQ(relaxed[t].particles.positions[i],
                  relaxed[0].particles.positions[i])
          << t + 1 << " threads, sphere " << i;
  }
} // namespace

/// L-BFGS takes the same path on any number of threads (the threaded
/// two-loop recursion sums its blocks in block order): the first 60
/// evaluations, short of the force-free state (66).
TEST(SolverEquilibrium, LbfgsTakesTheSamePathOnAnyNumberOfThreads)
{
  expect_the_same_path_on_any_number_of_threads<LbfgsRelaxation>(60);
}

/// FIRE takes the same path on any number of threads (the residual and
/// the Verlet search threaded, its vector algebra on one).
TEST(SolverEquilibrium, FireTakesTheSamePathOnAnyNumberOfThreads)
{
  expect_the_same_path_on_any_number_of_threads<FireRelaxation>(100);
}

/// The progress reports of a relaxation (reported at every evaluation with
/// a zero interval) follow its stopping test and change nothing: FIRE and
/// L-BFGS on the unrelaxed column report increasing evaluation counts up to
/// the result's, their last report is balanced below the tolerance times
/// the mean contact force of the closed form (every contact of the column
/// carries P), and the relaxed column is the same to the bit as without
/// reports.
TEST(SolverEquilibrium, RelaxationReportsFollowTheStoppingTestAndChangeNothing)
{
  const ContactModel model     = compax::testing::material1::contact_model();
  const int          N         = 6;
  const double       total     = 0.2 * R;
  const double       P         = column_force(N, total);
  const double       tolerance = 1e-9;
  FireRelaxation     fire;
  LbfgsRelaxation    lbfgs;
  for (Relaxation *minimiser :
       {static_cast<Relaxation *>(&fire), static_cast<Relaxation *>(&lbfgs)})
    {
      Bed              quiet = column_with_rattler(N, total);
      const FireResult q = minimiser->relax(quiet, model, tolerance, 100000);
      ASSERT_TRUE(q.converged);

      std::vector<RelaxationProgress> reports;
      minimiser->report_progress(
        [&reports](const RelaxationProgress &p) { reports.push_back(p); }, 0.0);
      Bed              bed = column_with_rattler(N, total);
      const FireResult r   = minimiser->relax(bed, model, tolerance, 100000);
      minimiser->report_progress({}, 0.0);

      ASSERT_TRUE(r.converged);
      ASSERT_GE(reports.size(), 2u);
      for (std::size_t k = 1; k < reports.size(); ++k)
        {
          EXPECT_GT(reports[k].evaluations, reports[k - 1].evaluations);
          EXPECT_GE(reports[k].seconds, reports[k - 1].seconds);
        }
      const RelaxationProgress &last = reports.back();
      EXPECT_EQ(last.evaluations, r.iterations);
      EXPECT_NEAR(last.balanced_below, tolerance * P, 1e-6 * tolerance * P);
      EXPECT_LE(last.largest_force, last.balanced_below);
      EXPECT_GT(reports.front().largest_force, 1e3 * last.balanced_below);

      EXPECT_EQ(r.iterations, q.iterations);
      for (std::size_t i = 0; i < bed.particles.size(); ++i)
        EXPECT_EQ(bed.particles.positions[i], quiet.particles.positions[i]);
    }
}

/// Algorithm 1 of Gonzalez 2018 as printed (the Gauss-Newton trust region
/// on |F|^2) balances the same unrelaxed column to the closed form of the
/// L-BFGS test: the column's stiffness is not singular along its net
/// forces, so the stationary point of |F|^2 is the equilibrium. The
/// rattler, without stiffness or force, is not moved.
TEST(SolverEquilibrium, LeastSquaresSolvesAColumnToTheClosedForm)
{
  const ContactModel model = compax::testing::material1::contact_model();
  const int          N     = 6;
  const double       total = 0.2 * R;
  Bed                bed   = column_with_rattler(N, total);

  EquilibriumOptions options;
  options.force_tolerance = 1e-9;
  options.step_tolerance  = 1e-12;
  LeastSquaresTrustRegion solver(options);
  const EquilibriumResult r = solver.solve(bed, model);
  ASSERT_TRUE(r.converged) << r.work.iterations << " iterations, residual "
                           << r.relative_residual;
  expect_column_closed_form(bed, model, N, total, options.force_tolerance);
}

// The RVE response database and the measured error of the continuum law
// fitted to it (coupling/rve_database, coupling/database_validation).
#include "coupling/database_validation.h"
#include "coupling/rve_database.h"
#include "fem/dpc_table.h"
#include "fem/drucker_prager_cap.h"
#include "fem/linear_elastic_material.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax;
using coupling::DatabaseRow;
using coupling::RveDatabase;

namespace
{
  Eigen::Matrix3d
  diagonal(const double a, const double b, const double c)
  {
    return Eigen::Vector3d(a, b, c).asDiagonal();
  }

  /// sigma = lambda tr(e) I + 2 mu e (Voigt).
  dem::Vector6d
  hooke(const Eigen::Matrix3d &e, const double E, const double nu)
  {
    const double    lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double    mu     = E / (2 * (1 + nu));
    Eigen::Matrix3d s      = 2 * mu * e;
    s.diagonal().array() += lambda * e.trace();
    dem::Vector6d v;
    v << s(0, 0), s(1, 1), s(2, 2), s(1, 2), s(0, 2), s(0, 1);
    return v;
  }

  DatabaseRow
  row(const int              branch,
      const std::string     &path,
      const Eigen::Matrix3d &F,
      const int              parent,
      const double           rho0)
  {
    DatabaseRow r{
      branch, path, rho0 / F.determinant(), 0.0, dem::Vector6d::Zero()};
    r.deformation = F;
    r.parent      = parent;
    return r;
  }

  coupling::DatabaseSpec
  small_spec(const std::uint64_t seed)
  {
    coupling::DatabaseSpec spec;
    spec.packing.particle_count = 80;
    spec.packing.seed           = seed;
    spec.final_density          = 0.76;
    spec.branch_densities       = {0.70, 0.76};
    spec.shear_steps            = 8;
    spec.radial_steps           = 4;
    return spec;
  }
} // namespace

/// A hypoelastic law driven along a tree of coaxial (diagonal) paths: the
/// log-strain increments sum to ln F, so the stress is Hooke's law of
/// ln F at every row, whatever branch it sits on; the density follows the
/// mass balance. A reference equal to that response has zero error; one
/// scaled by 1.1 is off by exactly 1/11 relative to itself.
TEST(DatabaseValidation, HypoelasticLawAlongATreeOfPaths)
{
  const double rho0 = 0.55, E = 2e9, nu = 0.3;
  RveDatabase  db;
  db.rows.push_back(
    row(-1, "compaction", Eigen::Matrix3d::Identity(), -1, rho0));
  int last = 0;
  for (int k = 1; k <= 5; ++k)
    {
      db.rows.push_back(
        row(-1, "compaction", diagonal(1, 1, std::exp(-0.02 * k)), last, rho0));
      last = k;
    }
  // Unloading and a radial probe from the last compaction state.
  int from = last;
  for (int k = 1; k <= 3; ++k)
    {
      db.rows.push_back(row(
        0, "unloading", diagonal(1, 1, std::exp(-0.1 + 0.01 * k)), from, rho0));
      from = static_cast<int>(db.rows.size()) - 1;
    }
  from = last;
  for (int k = 1; k <= 3; ++k)
    {
      const double ez = -0.1 - 0.01 * k, er = 0.5 * (-0.01 * k);
      db.rows.push_back(row(0,
                            "radial_0.50",
                            diagonal(std::exp(er), std::exp(er), std::exp(ez)),
                            from,
                            rho0));
      from = static_cast<int>(db.rows.size()) - 1;
    }
  for (DatabaseRow &r : db.rows)
    {
      const Eigen::Vector3d l = r.deformation.diagonal().array().log();
      r.stress                = hooke(l.asDiagonal(), E, nu);
    }

  const fem::LinearElasticMaterial law(E, nu);
  const auto sigma = coupling::drive_along_database(db, law);
  ASSERT_EQ(sigma.size(), db.rows.size());
  for (std::size_t r = 0; r < db.rows.size(); ++r)
    EXPECT_LT((sigma[r] - db.rows[r].stress).norm(),
              1e-9 * db.rows[r].stress.norm() + 1e-6)
      << "row " << r << " " << db.rows[r].path;

  const RveDatabase same = coupling::with_stresses(db, sigma);
  for (const auto &e : coupling::path_errors(db, same))
    {
      EXPECT_LT(e.stress_error, 1e-9) << e.path;
      EXPECT_EQ(e.training, e.path != "radial_0.50");
    }
  RveDatabase scaled = db;
  for (DatabaseRow &r : scaled.rows)
    r.stress *= 1.1;
  const auto errors = coupling::path_errors(scaled, db);
  ASSERT_EQ(errors.size(), 3u);
  for (const auto &e : errors)
    EXPECT_NEAR(e.stress_error, 0.1 / 1.1, 1e-12) << e.path;
  EXPECT_NEAR(coupling::pooled_stress_error(scaled, db, true),
              0.1 / 1.1,
              1e-12);
  EXPECT_NEAR(coupling::pooled_stress_error(scaled, db, false),
              0.1 / 1.1,
              1e-12);
}

/**
 * The Drucker-Prager Cap fitted to a small database (packing A), driven
 * along that database's paths and along every path of two more packings
 * (other seeds, not used in the fit), against the RVE's own
 * packing-to-packing scatter on the same paths, measured here.
 *
 * Tolerances, from the scatter s (RMS over the three pairs of packings of
 * the relative RMS stress difference on the same paths):
 *  - training points (the compaction states at the branch densities, which
 *    the cap is fitted through): the law driven along the compaction path
 *    meets them within 1 s (it was fitted to them, so it may miss them by
 *    no more than the noise of the data);
 *  - whole paths: within 3 s of the path class. A law fitted to one
 *    packing meets another at best within about s (the noise floor of the
 *    data), the remaining 2 s is the allowance for model-form error.
 *    Asserted for the compaction path (training) and the radial-strain
 *    probes (held out: not used in the fit) of A and of the two held-out
 *    packings.
 * Measured (80 particles, seeds 5/6/7): s = 0.146 (compaction), 0.154
 * (radial), 0.118 (training points); law 0.15-0.18, 0.31-0.34, 0.038.
 * Caps off by a factor 2 break both bounds (checked below). The
 * constant-volume shear probes are not bounded: the associated DPC runs to
 * its cap-shear corner there and its error (0.4-1.0) exceeds 3 s; they are
 * reported in validation.csv by `compax database`.
 */
TEST(RveDatabase, FittedCapAgainstTrainingAndHeldOutPaths)
{
  const dem::ContactModel  model = compax::testing::material1::contact_model();
  std::vector<RveDatabase> rve;
  // Frozen histories below jamming, as when the bounds below were set: on
  // the bonded path these 80-sphere gas packings scatter more (compaction
  // 0.19 instead of 0.15), and a cap off by a factor 0.5 (0.50) no longer
  // exceeds 3 s.
  for (const std::uint64_t seed : {5, 6, 7})
    {
      coupling::DatabaseSpec spec = small_spec(seed);
      spec.loading.consolidation  = dem::RveConsolidation::frozen_history;
      rve.push_back(coupling::build_rve_database(spec, model));
    }
  // The fitted table; `cap_scale` scales its cap pressures.
  auto table = [&](const double cap_scale) {
    fem::DpcTable t;
    for (const auto &r : coupling::fit_drucker_prager_cap(rve[0]))
      t.add_row(r.relative_density,
                r.cohesion,
                r.friction_angle_deg,
                r.cap_eccentricity,
                cap_scale * r.cap_pressure,
                r.youngs_modulus,
                r.poisson_ratio);
    return t;
  };
  const fem::DruckerPragerCap law(table(1.0));
  std::vector<RveDatabase>    fitted;
  for (const RveDatabase &db : rve)
    fitted.push_back(
      coupling::with_stresses(db, coupling::drive_along_database(db, law)));

  auto compaction = [](const RveDatabase &a, const RveDatabase &b) {
    for (const auto &e : coupling::path_errors(a, b))
      if (e.path == "compaction")
        return e.stress_error;
    ADD_FAILURE() << "no compaction path";
    return 0.0;
  };
  auto radial = [](const RveDatabase &a, const RveDatabase &b) {
    return coupling::pooled_stress_error(a, b, false);
  };
  // Scatter: RMS over the three pairs of packings.
  double s_compaction = 0.0, s_radial = 0.0;
  for (const auto &[i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}})
    {
      s_compaction += std::pow(compaction(rve[i], rve[j]), 2) / 3.0;
      s_radial += std::pow(radial(rve[i], rve[j]), 2) / 3.0;
    }
  s_compaction = std::sqrt(s_compaction);
  s_radial     = std::sqrt(s_radial);
  std::printf("packing scatter: compaction %.3f, radial probes %.3f\n",
              s_compaction,
              s_radial);
  ASSERT_GT(s_compaction, 0.0);
  ASSERT_GT(s_radial, 0.0);
  for (std::size_t k = 0; k < rve.size(); ++k)
    {
      std::printf("packing %zu: law error compaction %.3f, radial %.3f\n",
                  k,
                  compaction(rve[k], fitted[k]),
                  radial(rve[k], fitted[k]));
      EXPECT_LE(compaction(rve[k], fitted[k]), 3.0 * s_compaction)
        << "packing " << k;
      EXPECT_LE(radial(rve[k], fitted[k]), 3.0 * s_radial) << "packing " << k;
    }

  // The training points of the cap: the compaction states at the branch
  // densities (the rows where a branch starts), same rule.
  auto states = [](const RveDatabase &db) {
    std::vector<dem::Vector6d> out;
    for (const DatabaseRow &r : db.rows)
      for (const auto &br : db.branches)
        if (r.path == "compaction" && r.relative_density == br.relative_density)
          out.push_back(r.stress);
    return out;
  };
  auto at_branches = [&](const RveDatabase &a, const RveDatabase &b) {
    const auto sa = states(a), sb = states(b);
    EXPECT_EQ(sa.size(), a.branches.size());
    EXPECT_EQ(sa.size(), sb.size());
    double d2 = 0.0, s2 = 0.0;
    for (std::size_t k = 0; k < std::min(sa.size(), sb.size()); ++k)
      {
        d2 += (sb[k] - sa[k]).squaredNorm();
        s2 += sa[k].squaredNorm();
      }
    return std::sqrt(d2 / s2);
  };
  double s_points = 0.0;
  for (const auto &[i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}})
    s_points += std::pow(at_branches(rve[i], rve[j]), 2) / 3.0;
  s_points = std::sqrt(s_points);
  std::printf("training points: law %.3f, packing scatter %.3f\n",
              at_branches(rve[0], fitted[0]),
              s_points);
  // The cap passes through these states, so the law driven to them may
  // miss them by less than the noise of the data: tolerance 1 s.
  EXPECT_LE(at_branches(rve[0], fitted[0]), s_points);

  // The bound discriminates: a cap whose pressures are off by a factor
  // of 2 (as a fit to the wrong state would be) breaks it.
  for (const double scale : {0.5, 2.0})
    {
      const fem::DruckerPragerCap wrong(table(scale));
      const RveDatabase           w = coupling::with_stresses(
        rve[0], coupling::drive_along_database(rve[0], wrong));
      std::printf("cap x %.1f: compaction %.3f, radial %.3f\n",
                  scale,
                  compaction(rve[0], w),
                  radial(rve[0], w));
      EXPECT_GT(compaction(rve[0], w), 3.0 * s_compaction) << scale;
      EXPECT_GT(at_branches(rve[0], w), s_points) << scale;
    }
}

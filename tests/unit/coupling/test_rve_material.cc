#include "coupling/rve_material.h"

#include "fe2_test_support.h"


#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

using namespace compax;

namespace
{
  using compax::testing::material1;
  using compax::testing::small_drawn_spec;

  fem::MaterialIncrement
  uniaxial(const double eps_zz)
  {
    fem::MaterialIncrement inc;
    inc.strain_increment[2][2]      = eps_zz;
    inc.deformation_increment[2][2] = 1.0 + eps_zz;
    return inc;
  }

  /// Drives one point by committed uniaxial increments (the solver's
  /// commit is copying the trial history over the committed one).
  void
  compact(const coupling::RveMaterial &m,
          std::vector<double>         &h,
          const int                    steps,
          const double                 eps_zz)
  {
    std::vector<double>   trial(h.size());
    fem::MaterialResponse r;
    for (int k = 0; k < steps; ++k)
      {
        ASSERT_TRUE(m.evaluate(uniaxial(eps_zz), h, trial, r));
        h = trial;
      }
  }
} // namespace

/// Mass balance of the committed cell after committed increments, and a
/// cut (never committed) trial leaves no trace.
TEST(RveMaterial, CommitsOnlyCommittedIncrements)
{
  coupling::RveMaterial m(small_drawn_spec(), material1());
  std::vector<double>   h(m.n_history());
  m.initialize(0.60, h);
  const double rho0 = m.relative_density(h);
  compact(m, h, 20, -0.01);
  EXPECT_NEAR(m.relative_density(h), rho0 / std::pow(0.99, 20), 1e-12);

  std::vector<double>   a(h.size()), b(h.size()), cut(h.size());
  fem::MaterialResponse ra, rb, rc;
  ASSERT_TRUE(m.evaluate(uniaxial(-0.002), h, a, ra));
  // A trial that is thrown away (a step cut by the solver) ...
  m.evaluate(uniaxial(-0.02), h, cut, rc);
  // ... and the same increment again: identical.
  ASSERT_TRUE(m.evaluate(uniaxial(-0.002), h, b, rb));
  // (Equal to the equilibrium tolerance: the solver's trust radius
  // carries over from solve to solve.)
  const double sigma = ra.stress.norm();
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      EXPECT_NEAR(ra.stress[i][j], rb.stress[i][j], 1e-8 * sigma);
  EXPECT_LT(ra.stress[2][2], ra.stress[0][0]); // axial above lateral
  EXPECT_LT(ra.stress[0][0], 0.0);
}

/// The returned tangent against central differences of the returned
/// stress in the strain increment (each evaluation re-equilibrates from
/// the committed cell). The condensed tangent is taken with respect to a
/// strain of the trial configuration, so it differs from d sigma / d deps
/// by O(|deps|) = 2e-4, well below the 1e-3 asserted.
namespace
{
  /// The largest difference between the tangent of @p m at @p inc from
  /// state @p h and central differences of its stress, and the largest
  /// tangent entry.
  std::pair<double, double>
  tangent_error(const coupling::RveMaterial  &m,
                const std::vector<double>    &h,
                const fem::MaterialIncrement &inc,
                const double                  step)
  {
    std::vector<double>   out(h.size());
    fem::MaterialResponse r;
    EXPECT_TRUE(m.evaluate(inc, h, out, r));
    const dealii::SymmetricTensor<4, 3> C     = r.tangent;
    double                              worst = 0.0, scale = 0.0;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = k; l < 3; ++l)
        {
          fem::MaterialResponse  rp, rm;
          fem::MaterialIncrement ip = inc, im = inc;
          ip.strain_increment[k][l] += step;
          im.strain_increment[k][l] -= step;
          EXPECT_TRUE(m.evaluate(ip, h, out, rp));
          EXPECT_TRUE(m.evaluate(im, h, out, rm));
          // A symmetric perturbation of the (k, l) component changes both
          // eps_kl and eps_lk when k != l: d sigma = 2 C_ijkl step.
          const double factor = k == l ? 1.0 : 2.0;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              {
                const double fd
                  = (rp.stress[i][j] - rm.stress[i][j]) / (2.0 * step);
                worst = std::max(worst, std::abs(fd - factor * C[i][j][k][l]));
                scale = std::max(scale, std::abs(C[i][j][k][l]));
              }
        }
    return {worst, scale};
  }
} // namespace

/// A loose point whose trial passes its packing's jamming density within
/// the step stiffens at once by the packing's tangent on the part of the
/// increment beyond it: none short of the jamming density (floor only),
/// compression beyond it, and a tangent that is the derivative of that
/// stress (central differences).
TEST(RveMaterial, LoosePointPastItsJammingDensityStiffensWithExactTangent)
{
  coupling::RveMaterial m(small_drawn_spec(), material1());
  std::vector<double>   h(m.n_history());
  m.initialize(0.60, h);
  const double jam = m.jamming_density(0);
  ASSERT_GT(jam, 0.61);
  // One committed loose step to 0.5 % below the jamming density.
  compact(m, h, 1, 0.60 / (0.995 * jam) - 1.0);
  ASSERT_FALSE(coupling::RveMaterial::is_jammed(h));
  ASSERT_NEAR(m.relative_density(h), 0.995 * jam, 1e-12);

  std::vector<double>   out(h.size());
  fem::MaterialResponse short_of_jamming, past_jamming;
  ASSERT_TRUE(m.evaluate(uniaxial(-0.004), h, out, short_of_jamming));
  ASSERT_TRUE(m.evaluate(uniaxial(-0.010), h, out, past_jamming));
  // Short of it: the floor alone, E (1 - nu) / ((1 + nu)(1 - 2 nu)) eps.
  const double Ef = small_drawn_spec().tangent_floor_modulus;
  EXPECT_NEAR(short_of_jamming.stress[2][2] - m.stress(h)[2][2],
              -0.004 * Ef * 0.75 / (1.25 * 0.5),
              1e-9 * Ef);
  // Past it: the packing's stiffness on the strain beyond the jamming
  // density, far above the floor's.
  EXPECT_LT(past_jamming.stress[2][2] - m.stress(h)[2][2],
            -0.010 * Ef * 0.75 / (1.25 * 0.5) * 10.0);
  const auto [worst, scale] = tangent_error(m, h, uniaxial(-0.010), 1e-7);
  EXPECT_LT(worst, 1e-5 * scale);
}

TEST(RveMaterial, TangentIsDerivativeOfStressInTheIncrement)
{
  coupling::RveMaterial m(small_drawn_spec(), material1());
  std::vector<double>   h(m.n_history());
  m.initialize(0.60, h);
  compact(m, h, 20, -0.01);
  ASSERT_TRUE(coupling::RveMaterial::is_jammed(h));
  // The tangent of RVE and elastic floor together (the floor's stress is
  // integrated with the increment, so its derivative is the floor).
  const auto [worst, scale] = tangent_error(m, h, uniaxial(-2e-4), 1e-7);
  EXPECT_LT(worst, 1e-3 * scale);
}

#include "coupling/elastic_moduli.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cp = compax::coupling;
using cp::Stiffness6;

namespace
{
  /// Fourth-order tensor as a flat array C[i][j][k][l].
  using Tensor4 = double[3][3][3][3];

  int
  voigt(int i, int j)
  {
    static const int map[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};
    return map[i][j];
  }

  /// Engineering-shear Voigt -> tensor: C_ijkl = C_IJ without factors.
  void
  to_tensor(const Stiffness6 &C, Tensor4 &T)
  {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            T[i][j][k][l] = C(voigt(i, j), voigt(k, l));
  }

  Stiffness6
  to_voigt(const Tensor4 &T)
  {
    static const int pairs[6][2]
      = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
    Stiffness6 C;
    for (int I = 0; I < 6; ++I)
      for (int J = 0; J < 6; ++J)
        C(I, J) = T[pairs[I][0]][pairs[I][1]][pairs[J][0]][pairs[J][1]];
    return C;
  }

  double
  frobenius(const Tensor4 &A, const Tensor4 &B)
  {
    double s = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            s += A[i][j][k][l] * B[i][j][k][l];
    return s;
  }

  /// A symmetric positive definite, fully anisotropic stiffness [Pa].
  Stiffness6
  random_stiffness(unsigned seed)
  {
    std::mt19937                           rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Stiffness6                             A;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        A(i, j) = u(rng);
    return 1.0e9 * (A * A.transpose() + 2.0 * Stiffness6::Identity());
  }

  /// Isotropic stiffness from its textbook Lame form, written independently
  /// of the library.
  Stiffness6
  lame_stiffness(double E, double nu)
  {
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double mu     = E / (2 * (1 + nu));
    Stiffness6   C;
    C << lambda + 2 * mu, lambda, lambda, 0, 0, 0, //
      lambda, lambda + 2 * mu, lambda, 0, 0, 0,    //
      lambda, lambda, lambda + 2 * mu, 0, 0, 0,    //
      0, 0, 0, mu, 0, 0,                           //
      0, 0, 0, 0, mu, 0,                           //
      0, 0, 0, 0, 0, mu;
    return C;
  }

  /// Compliance of a transversely isotropic solid about z, from its
  /// engineering constants (Lekhnitskii's form).
  Stiffness6
  ti_compliance(double Ep, double nup, double Ez, double nuzp, double Gz)
  {
    Stiffness6 S = Stiffness6::Zero();
    S(0, 0) = S(1, 1) = 1 / Ep;
    S(0, 1) = S(1, 0) = -nup / Ep;
    S(0, 2) = S(2, 0) = S(1, 2) = S(2, 1) = -nuzp / Ez;
    S(2, 2)                               = 1 / Ez;
    S(3, 3) = S(4, 4) = 1 / Gz;
    S(5, 5)           = 2 * (1 + nup) / Ep;
    return S;
  }

  double
  max_relative_difference(const Stiffness6 &A, const Stiffness6 &B)
  {
    return (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff();
  }
} // namespace

TEST(ElasticModuli, IsotropicStiffnessProjectsBackToItsConstants)
{
  for (const auto &[E, nu] : {std::pair{3.2e9, 0.31},
                              std::pair{210e9, 0.0},
                              std::pair{1.0e6, -0.4},
                              std::pair{5.0e9, 0.49}})
    {
      const Stiffness6 C = lame_stiffness(E, nu);
      EXPECT_LT(max_relative_difference(cp::isotropic_stiffness(E, nu), C),
                1e-15);
      const cp::IsotropicModuli m = cp::isotropic_projection(C);
      EXPECT_NEAR(m.youngs_modulus / E, 1.0, 1e-12);
      EXPECT_NEAR(m.poisson_ratio, nu, 1e-12);
      EXPECT_NEAR(m.bulk_modulus / (E / (3 * (1 - 2 * nu))), 1.0, 1e-12);
      EXPECT_NEAR(m.shear_modulus / (E / (2 * (1 + nu))), 1.0, 1e-12);
    }
}

TEST(ElasticModuli, IsotropicProjectionIsFrobeniusOrthogonal)
{
  // J = I(x)I/3 and K = I^s - J, built index by index.
  Tensor4 J, K;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          {
            J[i][j][k][l] = (i == j) * (k == l) / 3.0;
            K[i][j][k][l] = 0.5 * ((i == k) * (j == l) + (i == l) * (j == k))
                            - J[i][j][k][l];
          }
  for (unsigned seed : {1u, 2u, 3u})
    {
      const Stiffness6          C = random_stiffness(seed);
      const cp::IsotropicModuli m = cp::isotropic_projection(C);
      Tensor4                   T, R;
      to_tensor(C, T);
      // 3K = C::J / (J::J) and 2G = C::K / (K::K), J::J = 1, K::K = 5.
      EXPECT_NEAR(m.bulk_modulus / (frobenius(T, J) / 3.0), 1.0, 1e-12);
      EXPECT_NEAR(m.shear_modulus / (frobenius(T, K) / 10.0), 1.0, 1e-12);
      // The residual C - (3K J + 2G K) is orthogonal to both.
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
              R[i][j][k][l] = T[i][j][k][l] - 3 * m.bulk_modulus * J[i][j][k][l]
                              - 2 * m.shear_modulus * K[i][j][k][l];
      const double scale = std::sqrt(frobenius(T, T));
      EXPECT_LT(std::abs(frobenius(R, J)), 1e-13 * scale);
      EXPECT_LT(std::abs(frobenius(R, K)), 1e-13 * scale);
    }
}

TEST(ElasticModuli, TransverselyIsotropicConstantsAreRecovered)
{
  // Compacted-tablet-like anisotropy: stiffer in-plane than axially.
  const double     Ep = 6.0e9, nup = 0.21, Ez = 4.5e9, nuzp = 0.17, Gz = 1.9e9;
  const Stiffness6 C_ref = ti_compliance(Ep, nup, Ez, nuzp, Gz).inverse();

  const cp::TransverselyIsotropicModuli in{Ep, nup, Ez, nuzp, Gz};
  const Stiffness6 C = cp::transversely_isotropic_stiffness(in);
  EXPECT_LT(max_relative_difference(C, C_ref), 1e-12);
  // Transverse isotropy: C66 = (C11 - C12) / 2.
  EXPECT_NEAR(C(5, 5) / (0.5 * (C(0, 0) - C(0, 1))), 1.0, 1e-12);

  const cp::TransverselyIsotropicModuli out
    = cp::transversely_isotropic_moduli(C_ref);
  EXPECT_NEAR(out.youngs_in_plane / Ep, 1.0, 1e-12);
  EXPECT_NEAR(out.poisson_in_plane, nup, 1e-12);
  EXPECT_NEAR(out.youngs_axial / Ez, 1.0, 1e-12);
  EXPECT_NEAR(out.poisson_axial_to_plane, nuzp, 1e-12);
  EXPECT_NEAR(out.shear_axial / Gz, 1.0, 1e-12);

  // The isotropic special case reduces to the Lame stiffness.
  const double     E = 3.0e9, nu = 0.3;
  const Stiffness6 C_iso
    = cp::transversely_isotropic_stiffness({E, nu, E, nu, E / (2 * (1 + nu))});
  EXPECT_LT(max_relative_difference(C_iso, lame_stiffness(E, nu)), 1e-12);
}

TEST(ElasticModuli, TransverselyIsotropicProjectionIsTheRotationalAverage)
{
  // Average of Q C Q over rotations about z: the integrand is a
  // trigonometric polynomial of degree 4 in the angle, so 8 equally spaced
  // angles integrate it exactly.
  const Stiffness6 C = random_stiffness(7);
  Tensor4          T, A;
  to_tensor(C, T);
  for (auto &a : A)
    for (auto &b : a)
      for (auto &c : b)
        for (double &d : c)
          d = 0.0;
  const int n_angles = 8;
  for (int n = 0; n < n_angles; ++n)
    {
      const double theta = 2.0 * M_PI * n / n_angles;
      const double c = std::cos(theta), s = std::sin(theta);
      const double Q[3][3] = {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
              {
                double sum = 0.0;
                for (int p = 0; p < 3; ++p)
                  for (int q = 0; q < 3; ++q)
                    for (int r = 0; r < 3; ++r)
                      for (int t = 0; t < 3; ++t)
                        sum += Q[i][p] * Q[j][q] * Q[k][r] * Q[l][t]
                               * T[p][q][r][t];
                A[i][j][k][l] += sum / n_angles;
              }
    }
  const Stiffness6 P = cp::transversely_isotropic_projection(C);
  EXPECT_LT(max_relative_difference(P, to_voigt(A)), 1e-13);
  // A projection: applying it twice changes nothing.
  EXPECT_LT(max_relative_difference(cp::transversely_isotropic_projection(P),
                                    P),
            1e-15);
}

TEST(ElasticModuli, ComplianceTimesStiffnessIsIdentity)
{
  for (const Stiffness6 &C :
       {random_stiffness(11),
        cp::isotropic_stiffness(3.0e9, 0.3),
        cp::transversely_isotropic_stiffness({6e9, 0.2, 4e9, 0.15, 1.5e9})})
    {
      const Stiffness6 S = cp::compliance(C);
      EXPECT_LT((S * C - Stiffness6::Identity()).cwiseAbs().maxCoeff(), 1e-12);
      EXPECT_LT((C * S - Stiffness6::Identity()).cwiseAbs().maxCoeff(), 1e-12);
    }
  // Isotropic compliance in closed form: S11 = 1/E, S12 = -nu/E, S44 = 1/G.
  const double     E = 3.0e9, nu = 0.3;
  const Stiffness6 S = cp::compliance(cp::isotropic_stiffness(E, nu));
  EXPECT_NEAR(S(0, 0) * E, 1.0, 1e-12);
  EXPECT_NEAR(S(0, 1) * E, -nu, 1e-12);
  EXPECT_NEAR(S(3, 3) * E / (2 * (1 + nu)), 1.0, 1e-12);

  Stiffness6 unstable = cp::isotropic_stiffness(3.0e9, 0.3);
  unstable(3, 3)      = -1.0e9;
  EXPECT_THROW(cp::compliance(unstable), std::domain_error);
  Stiffness6 skew = cp::isotropic_stiffness(3.0e9, 0.3);
  skew(0, 1) *= 1.5;
  EXPECT_THROW(cp::compliance(skew), std::domain_error);
}

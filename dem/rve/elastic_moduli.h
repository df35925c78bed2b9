#pragma once

#include <Eigen/Dense>

namespace compax::dem
{
  /**
   * Elastic constants from a homogenized 6x6 stiffness.
   *
   * Convention (Voigt, engineering shear strains): stress and strain are
   * ordered (11, 22, 33, 23, 13, 12),
   *   sigma = (s11, s22, s33, s23, s13, s12),
   *   eps   = (e11, e22, e33, 2 e23, 2 e13, 2 e12),
   * and sigma = C eps. Then C_IJ equals the tensor component C_ijkl of the
   * index pairs I = (ij), J = (kl) without factors, C is symmetric, the
   * strain energy is eps^T C eps / 2, and for an isotropic solid
   * C_44 = C_55 = C_66 = G. The compliance S = C^{-1} maps sigma to eps in
   * the same convention (S_44 = 1/G). Axis 3 (z) is the compaction axis.
   */
  using Stiffness6 = Eigen::Matrix<double, 6, 6>;

  /// Isotropic moduli; any two determine the others.
  struct IsotropicModuli
  {
    double bulk_modulus;   ///< K [Pa]
    double shear_modulus;  ///< G [Pa]
    double youngs_modulus; ///< E = 9KG/(3K+G) [Pa]
    double poisson_ratio;  ///< nu = (3K-2G)/(2(3K+G)) [-]

    static IsotropicModuli
    from_bulk_shear(double K, double G);
  };

  /**
   * Transversely isotropic constants about the z (3) axis. Poisson ratios
   * follow nu_ij = -eps_j / eps_i under uniaxial stress along i, so
   *   S_11 = 1/E_p, S_12 = -nu_p/E_p, S_13 = -nu_zp/E_z, S_33 = 1/E_z,
   *   S_44 = S_55 = 1/G_zp, S_66 = 2(1 + nu_p)/E_p,
   * and the other in-plane/axial ratio is nu_pz = nu_zp E_p / E_z.
   */
  struct TransverselyIsotropicModuli
  {
    double youngs_in_plane;  ///< E_p, in the x-y plane [Pa]
    double poisson_in_plane; ///< nu_p: in-plane contraction, in-plane load [-]
    double youngs_axial;     ///< E_z, along the axis [Pa]
    double
      poisson_axial_to_plane; ///< nu_zp: in-plane contraction, axial load [-]
    double shear_axial;       ///< G_zp = C_44 = C_55, planes holding z [Pa]
  };

  /// Isotropic stiffness from E [Pa] and nu [-] (C_11 = lambda + 2 mu,
  /// C_12 = lambda, C_44 = mu).
  Stiffness6
  isotropic_stiffness(double youngs_modulus, double poisson_ratio);

  /// Transversely isotropic stiffness about z, the inverse of the
  /// compliance given in TransverselyIsotropicModuli.
  Stiffness6
  transversely_isotropic_stiffness(const TransverselyIsotropicModuli &m);

  /**
   * Compliance S = C^{-1} by a Cholesky solve of C S = I. Throws
   * std::domain_error unless C is symmetric (to 1e-10 relative) and
   * positive definite, i.e. a stable elastic stiffness.
   */
  Stiffness6
  compliance(const Stiffness6 &C);

  /**
   * Isotropic part of C: the Frobenius-orthogonal projection of the
   * fourth-order tensor onto span{J, K} (J = I(x)I/3, K = I^s - J), which
   * gives 3K = C::J and 2G = C::K/5, i.e. the Voigt averages
   *   K = (C11+C22+C33 + 2(C12+C13+C23)) / 9,
   *   G = (C11+C22+C33 - (C12+C13+C23) + 3(C44+C55+C66)) / 15.
   * For an isotropic C it returns the exact constants.
   */
  IsotropicModuli
  isotropic_projection(const Stiffness6 &C);

  /**
   * Transversely isotropic part of C about z: the average of C over all
   * rotations about z, which is also its Frobenius-orthogonal projection
   * onto the transversely isotropic tensors. In Voigt form it keeps
   * C33, C13 = C23 = (C13 + C23)/2, C44 = C55 = (C44 + C55)/2 and
   *   C11 = C22 = 3/8 (C11 + C22) + C12/4 + C66/2,
   *   C12 = (C11 + C22)/8 + 3/4 C12 - C66/2,  C66 = (C11 - C12)/2,
   * and zeroes every other entry.
   */
  Stiffness6
  transversely_isotropic_projection(const Stiffness6 &C);

  /// The five constants of the transversely isotropic part of C about z,
  /// read from the compliance of transversely_isotropic_projection(C).
  TransverselyIsotropicModuli
  transversely_isotropic_moduli(const Stiffness6 &C);
} // namespace compax::dem

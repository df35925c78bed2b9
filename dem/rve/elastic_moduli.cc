#include "dem/rve/elastic_moduli.h"

#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  IsotropicModuli
  IsotropicModuli::from_bulk_shear(const double K, const double G)
  {
    IsotropicModuli m;
    m.bulk_modulus   = K;
    m.shear_modulus  = G;
    m.youngs_modulus = 9.0 * K * G / (3.0 * K + G);
    m.poisson_ratio  = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
    return m;
  }

  Stiffness6
  isotropic_stiffness(const double E, const double nu)
  {
    if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5))
      throw std::invalid_argument(
        "isotropic_stiffness: need E > 0 and -1 < nu < 1/2");
    const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    const double mu     = E / (2.0 * (1.0 + nu));
    Stiffness6   C      = Stiffness6::Zero();
    C.topLeftCorner<3, 3>().setConstant(lambda);
    for (int i = 0; i < 3; ++i)
      {
        C(i, i) += 2.0 * mu;
        C(i + 3, i + 3) = mu;
      }
    return C;
  }

  Stiffness6
  transversely_isotropic_stiffness(const TransverselyIsotropicModuli &m)
  {
    const double Ep = m.youngs_in_plane, Ez = m.youngs_axial;
    if (!(Ep > 0.0) || !(Ez > 0.0) || !(m.shear_axial > 0.0))
      throw std::invalid_argument(
        "transversely_isotropic_stiffness: moduli must be > 0");
    Stiffness6 S = Stiffness6::Zero();
    S(0, 0) = S(1, 1) = 1.0 / Ep;
    S(0, 1) = S(1, 0) = -m.poisson_in_plane / Ep;
    S(0, 2) = S(2, 0) = S(1, 2) = S(2, 1) = -m.poisson_axial_to_plane / Ez;
    S(2, 2)                               = 1.0 / Ez;
    S(3, 3) = S(4, 4) = 1.0 / m.shear_axial;
    S(5, 5)           = 2.0 * (1.0 + m.poisson_in_plane) / Ep;
    // The stiffness of a stable solid is the inverse of an SPD compliance;
    // compliance() checks that and inverts it.
    return compliance(S);
  }

  Stiffness6
  compliance(const Stiffness6 &C)
  {
    const double scale = C.cwiseAbs().maxCoeff();
    if (!(scale > 0.0) || !C.allFinite())
      throw std::domain_error("compliance: stiffness is zero or not finite");
    if ((C - C.transpose()).cwiseAbs().maxCoeff() > 1e-10 * scale)
      throw std::domain_error("compliance: stiffness is not symmetric");
    const Stiffness6             C_sym = 0.5 * (C + C.transpose());
    const Eigen::LLT<Stiffness6> llt(C_sym);
    if (llt.info() != Eigen::Success)
      throw std::domain_error("compliance: stiffness is not positive definite");
    return llt.solve(Stiffness6::Identity());
  }

  IsotropicModuli
  isotropic_projection(const Stiffness6 &C)
  {
    const double diagonal = C(0, 0) + C(1, 1) + C(2, 2);
    const double off_diagonal
      = 0.5 * (C(0, 1) + C(1, 0) + C(0, 2) + C(2, 0) + C(1, 2) + C(2, 1));
    const double shear = C(3, 3) + C(4, 4) + C(5, 5);
    const double K     = (diagonal + 2.0 * off_diagonal) / 9.0;
    const double G     = (diagonal - off_diagonal + 3.0 * shear) / 15.0;
    return IsotropicModuli::from_bulk_shear(K, G);
  }

  Stiffness6
  transversely_isotropic_projection(const Stiffness6 &C_in)
  {
    const Stiffness6 C   = 0.5 * (C_in + C_in.transpose());
    const double     a11 = C(0, 0) + C(1, 1);
    const double     c11 = 0.375 * a11 + 0.25 * C(0, 1) + 0.5 * C(5, 5);
    const double     c12 = 0.125 * a11 + 0.75 * C(0, 1) - 0.5 * C(5, 5);
    const double     c13 = 0.5 * (C(0, 2) + C(1, 2));
    const double     c44 = 0.5 * (C(3, 3) + C(4, 4));
    Stiffness6       P   = Stiffness6::Zero();
    P(0, 0) = P(1, 1) = c11;
    P(0, 1) = P(1, 0) = c12;
    P(0, 2) = P(2, 0) = P(1, 2) = P(2, 1) = c13;
    P(2, 2)                               = C(2, 2);
    P(3, 3) = P(4, 4) = c44;
    P(5, 5)           = 0.5 * (c11 - c12);
    return P;
  }

  TransverselyIsotropicModuli
  transversely_isotropic_moduli(const Stiffness6 &C)
  {
    const Stiffness6 S = compliance(transversely_isotropic_projection(C));
    TransverselyIsotropicModuli m;
    m.youngs_in_plane        = 1.0 / S(0, 0);
    m.poisson_in_plane       = -S(0, 1) * m.youngs_in_plane;
    m.youngs_axial           = 1.0 / S(2, 2);
    m.poisson_axial_to_plane = -S(0, 2) * m.youngs_axial;
    m.shear_axial            = 1.0 / S(3, 3);
    return m;
  }
} // namespace compax::dem

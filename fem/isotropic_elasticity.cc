#include "fem/isotropic_elasticity.h"

#include <stdexcept>

namespace compax::fem
{
  namespace
  {
    void
    check(double E, double nu)
    {
      if (!(E > 0.0))
        throw std::invalid_argument("isotropic elasticity: E must be > 0");
      if (!(nu > -1.0 && nu < 0.5))
        throw std::invalid_argument(
          "isotropic elasticity: nu must lie in (-1, 1/2)");
    }
  } // namespace

  double
  lame_lambda(const double E, const double nu)
  {
    check(E, nu);
    return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  }

  double
  shear_modulus(const double E, const double nu)
  {
    check(E, nu);
    return E / (2.0 * (1.0 + nu));
  }

  dealii::SymmetricTensor<4, 3>
  isotropic_stiffness_tensor(const double E, const double nu)
  {
    const double                        lambda = lame_lambda(E, nu);
    const double                        mu     = shear_modulus(E, nu);
    const dealii::SymmetricTensor<2, 3> I = dealii::unit_symmetric_tensor<3>();
    return lambda * dealii::outer_product(I, I)
           + 2.0 * mu * dealii::identity_tensor<3>();
  }
} // namespace compax::fem

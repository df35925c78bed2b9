#pragma once

#include <deal.II/base/symmetric_tensor.h>

namespace compax::fem
{
  /**
   * Isotropic linear elastic stiffness C = lambda I (x) I + 2 mu I^s as a
   * 3-D fourth-order tensor, so that sigma = C : epsilon with tension
   * positive. The 3-D form serves the axisymmetric model too, whose strain
   * has a hoop component.
   * @param youngs_modulus E [Pa], > 0
   * @param poisson_ratio nu [-], in (-1, 1/2)
   */
  dealii::SymmetricTensor<4, 3>
  isotropic_stiffness_tensor(double youngs_modulus, double poisson_ratio);

  /// First Lame parameter lambda = E nu / ((1 + nu)(1 - 2 nu)) [Pa].
  double
  lame_lambda(double youngs_modulus, double poisson_ratio);

  /// Shear modulus mu = E / (2 (1 + nu)) [Pa].
  double
  shear_modulus(double youngs_modulus, double poisson_ratio);
} // namespace compax::fem

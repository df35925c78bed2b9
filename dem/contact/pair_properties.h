#pragma once

#include <limits>

/**
 * @file
 * Mixing rules for the effective properties of a pair of bodies. A rigid
 * wall is a body of infinite radius, modulus and plastic stiffness, so that
 * the same formulas give the sphere-on-flat case: 1/inf = 0 in IEEE
 * arithmetic.
 */

namespace compax::dem
{
  /// Radius, modulus or stiffness of a rigid flat wall.
  inline constexpr double rigid = std::numeric_limits<double>::infinity();

  /// Effective radius R = (1/R1 + 1/R2)^{-1} [m].
  double
  effective_radius(double R1, double R2);

  /// Effective plane-strain modulus
  /// E = ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)^{-1} [Pa]
  /// (Gonzalez 2018 after Eq. 1; Giannis 2021 prints it without the inverse,
  /// an erratum).
  double
  effective_modulus(double E1, double nu1, double E2, double nu2);

  /// Effective plastic stiffness (1/kappa1^m + 1/kappa2^m)^{-1/m} [Pa], the
  /// kappa-dependent factor of n_p (Gonzalez 2018 after Eq. 1).
  double
  effective_plastic_stiffness(double kappa1, double kappa2, double m);
} // namespace compax::dem

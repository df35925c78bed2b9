#include "dem/contact/pair_properties.h"

#include <cmath>

namespace compax::dem
{
  double
  effective_radius(const double R1, const double R2)
  {
    return 1.0 / (1.0 / R1 + 1.0 / R2);
  }

  double
  effective_modulus(const double E1,
                    const double nu1,
                    const double E2,
                    const double nu2)
  {
    return 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
  }

  double
  effective_plastic_stiffness(const double kappa1,
                              const double kappa2,
                              const double m)
  {
    return std::pow(std::pow(kappa1, -m) + std::pow(kappa2, -m), -1.0 / m);
  }
} // namespace compax::dem

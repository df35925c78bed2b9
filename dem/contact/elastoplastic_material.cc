#include "dem/contact/elastoplastic_material.h"

#include "dem/contact/pair_properties.h"

#include <cmath>

namespace compax::dem
{
  ElastoplasticMaterial
  ElastoplasticMaterial::rigid_wall(const double plastic_exponent)
  {
    return {rigid, 0.0, rigid, plastic_exponent};
  }

  double
  fracture_toughness_from_energies(const ElastoplasticMaterial &material1,
                                   const double                 omega1,
                                   const ElastoplasticMaterial &material2,
                                   const double                 omega2,
                                   const double plastic_dissipation)
  {
    const double E = effective_modulus(material1.youngs_modulus,
                                       material1.poisson_ratio,
                                       material2.youngs_modulus,
                                       material2.poisson_ratio);
    return std::sqrt(2.0 * (omega1 + omega2 + plastic_dissipation) * E);
  }
} // namespace compax::dem

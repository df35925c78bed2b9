#pragma once

// The elastic constants of a homogenized stiffness live in the deal.II-free
// dem/rve/elastic_moduli.h, so that dem::RvePathStudy reports moduli; the
// coupling layer keeps its names for its callers.

#include "dem/rve/elastic_moduli.h"

namespace compax::coupling
{
  using dem::compliance;
  using dem::isotropic_projection;
  using dem::isotropic_stiffness;
  using dem::IsotropicModuli;
  using dem::Stiffness6;
  using dem::transversely_isotropic_moduli;
  using dem::transversely_isotropic_projection;
  using dem::transversely_isotropic_stiffness;
  using dem::TransverselyIsotropicModuli;
} // namespace compax::coupling

#include "dem/solver/contact_assembler.h"

#include "dem/numbers.h"

#include <cmath>

#include <omp.h>

namespace compax::dem
{
  double
  unloading_stiffness(const BondedElastoplasticLaw &law, const double a)
  {
    return 16.0 * law.constants().effective_modulus * a / (3.0 * pi);
  }

  template class PairAssembler<Bed>;
} // namespace compax::dem

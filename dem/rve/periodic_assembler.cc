#include "dem/rve/periodic_assembler.h"

namespace compax::dem
{
  template class PairAssembler<PeriodicBed>;
} // namespace compax::dem

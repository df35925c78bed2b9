#include "dem/solver/verlet_list.h"

#include <atomic>

namespace compax::dem
{
  void
  VerletList::record_build(const ParticleSystem &particles)
  {
    static std::atomic<std::uint64_t> counter{0};
    reference_positions = particles.positions;
    built               = true;
    revision_           = ++counter;
  }
} // namespace compax::dem

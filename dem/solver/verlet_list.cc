#include "dem/solver/verlet_list.h"

#include <atomic>

namespace compax::dem
{
  std::uint64_t
  next_contact_list_revision()
  {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
  }
} // namespace compax::dem

#pragma once

#include <cstddef>

namespace compax::dem
{
  /// Particles of a bed from which a loop over them (the stiffness
  /// product's block rows, the Verlet list's cell search and displacement
  /// test) is shared among the threads: below, opening a parallel region
  /// costs more than it shares.
  inline constexpr std::ptrdiff_t parallel_particles = 2048;
} // namespace compax::dem

#pragma once

// The starting bed of the die tests: a ballistic deposit in the rigid
// cylindrical die.

#include "dem/die/die_setup.h"

#include <cstddef>
#include <cstdint>

namespace compax::testing
{
  /// A die of @p diameter [m] filled by ballistic deposition of @p n
  /// spheres of the default size distribution (monodisperse, R = 220 um)
  /// with @p seed.
  inline dem::Bed
  deposited_die(const std::size_t   n,
                const double        diameter,
                const std::uint64_t seed)
  {
    dem::DepositionParameters dp;
    dp.n_particles  = n;
    dp.die_diameter = diameter;
    dp.seed         = seed;
    return dem::fill_die(dp);
  }
} // namespace compax::testing

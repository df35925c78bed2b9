#pragma once

// The slightly polydisperse periodic cells of the RVE tests: a spread of
// radii keeps the packing from crystallising.

#include "dem/rve/periodic_packing.h"

#include <cstddef>
#include <cstdint>

namespace compax::testing
{
  /// A periodic packing of @p n spheres whose radii are log-normal about
  /// @p R (sigma of ln R 0.1) truncated to [0.8 R, @p largest_ratio R], at
  /// relative density @p relative_density, drawn with @p seed.
  inline dem::PeriodicPackingSpec
  narrow_polydisperse_cell(const std::size_t   n,
                           const double        R,
                           const double        largest_ratio,
                           const double        relative_density,
                           const std::uint64_t seed)
  {
    dem::PeriodicPackingSpec spec;
    spec.particle_count      = n;
    spec.sizes.median_radius = R;
    spec.sizes.log_sigma     = 0.1;
    spec.sizes.min_radius    = 0.8 * R;
    spec.sizes.max_radius    = largest_ratio * R;
    spec.relative_density    = relative_density;
    spec.seed                = seed;
    return spec;
  }
} // namespace compax::testing

#include "dem/packing/random_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  double
  RandomSource::normal()
  {
    constexpr double two_pi = 6.28318530717958647692;
    const double     u1     = 1.0 - uniform(); // (0, 1]
    const double     u2     = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(two_pi * u2);
  }

  double
  SizeDistribution::sample(RandomSource &random) const
  {
    if (log_sigma <= 0.0)
      return median_radius;
    if (!(min_radius < max_radius) || min_radius > median_radius * 1e3
        || max_radius < median_radius * 1e-3)
      throw std::invalid_argument("log-normal cut-offs leave no radius");
    for (int attempt = 0; attempt < 100000; ++attempt)
      {
        const double r = median_radius * std::exp(log_sigma * random.normal());
        if (r >= min_radius && r <= max_radius)
          return r;
      }
    throw std::runtime_error("log-normal cut-offs reject every sample");
  }

  double
  SizeDistribution::largest() const
  {
    if (log_sigma <= 0.0)
      return median_radius;
    return std::min(max_radius, median_radius * std::exp(6.0 * log_sigma));
  }
} // namespace compax::dem

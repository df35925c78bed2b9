#include "dem/periodic/size_distribution_fit.h"

#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// Standard normal quantile of 0.9.
    constexpr double z90 = 1.2815515655446004;

    /// Standard normal quantile by bisection on erfc (used rarely).
    double
    normal_quantile(const double q)
    {
      double lo = -40.0, hi = 40.0;
      for (int it = 0; it < 200; ++it)
        {
          const double mid = 0.5 * (lo + hi);
          if (0.5 * std::erfc(-mid / std::sqrt(2.0)) < q)
            lo = mid;
          else
            hi = mid;
        }
      return 0.5 * (lo + hi);
    }
  } // namespace

  double
  VolumeLogNormal::quantile(const double q) const
  {
    return median_diameter * std::exp(log_sigma * normal_quantile(q));
  }

  VolumeLogNormal
  fit_volume_log_normal(const double x10, const double x50, const double x90)
  {
    if (!(x10 > 0.0 && x10 < x50 && x50 < x90))
      throw std::invalid_argument(
        "size distribution: need 0 < x10 < x50 < x90");
    const double mu    = (std::log(x10) + std::log(x50) + std::log(x90)) / 3.0;
    const double sigma = std::log(x90 / x10) / (2.0 * z90);
    return {std::exp(mu), sigma};
  }

  SizeDistribution
  number_radius_distribution(const VolumeLogNormal &volume_distribution,
                             const double           min_diameter,
                             const double           max_diameter)
  {
    if (!(min_diameter >= 0.0 && max_diameter > min_diameter))
      throw std::invalid_argument(
        "size distribution: need 0 <= minimum < maximum diameter");
    const double     s = volume_distribution.log_sigma;
    SizeDistribution psd;
    psd.median_radius
      = 0.5 * volume_distribution.median_diameter * std::exp(-3.0 * s * s);
    psd.log_sigma  = s;
    psd.min_radius = 0.5 * min_diameter;
    psd.max_radius = 0.5 * max_diameter;
    return psd;
  }
} // namespace compax::dem

#pragma once

#include "dem/packing/random_source.h"

namespace compax::dem
{
  /**
   * A log-normal particle size distribution by volume (Q3), as powder
   * characterisation reports it: ln x normal with median x_50,3 and
   * standard deviation sigma.
   */
  struct VolumeLogNormal
  {
    /// Median diameter of the volume distribution x_50,3 [m].
    double median_diameter = 0.0;
    /// Standard deviation of ln x [-].
    double log_sigma = 0.0;

    /// Diameter of the volume quantile q in (0, 1) [m].
    double
    quantile(double q) const;
  };

  /**
   * Least-squares fit in ln x of a log-normal to the three volume quantiles
   * x10, x50, x90 of Giannis 2021 Table 1: ln x_q = mu + z_q sigma with
   * z = -1.2816, 0, 1.2816, so mu is the mean of the three logarithms and
   * sigma = ln(x90/x10) / (2 * 1.2816). (Three quantiles, two parameters:
   * the fitted median differs from the measured x50 when the measured
   * distribution is skewed, as for MCC-A.)
   */
  VolumeLogNormal
  fit_volume_log_normal(double x10, double x50, double x90);

  /**
   * The particle RADII to sample so that the VOLUME distribution is the
   * given one: by the Hatch-Choate relation the number distribution is
   * log-normal with the same sigma and median x_50,0 = x_50,3
   * exp(-3 sigma^2). Truncated by rejection to diameters in
   * [min_diameter, max_diameter] (the cut-offs; a cell must be wider than
   * the largest particle).
   */
  SizeDistribution
  number_radius_distribution(const VolumeLogNormal &volume_distribution,
                             double                 min_diameter,
                             double                 max_diameter);
} // namespace compax::dem

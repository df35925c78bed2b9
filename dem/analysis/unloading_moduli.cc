#include "dem/analysis/unloading_moduli.h"

#include <algorithm>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// Slope of the least-squares line through (x_i, y_i).
    double
    slope(const std::vector<double> &x, const std::vector<double> &y)
    {
      const double n  = static_cast<double>(x.size());
      double       sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          sx += x[i];
          sy += y[i];
          sxx += x[i] * x[i];
          sxy += x[i] * y[i];
        }
      return (n * sxy - sx * sy) / (n * sxx - sx * sx);
    }
  } // namespace

  UnloadingModuli
  moduli_from_unloading(const std::vector<double> &axial_strain,
                        const std::vector<double> &axial_pressure,
                        const std::vector<double> &radial_pressure)
  {
    if (axial_strain.size() != axial_pressure.size()
        || axial_strain.size() != radial_pressure.size())
      throw std::invalid_argument(
        "moduli_from_unloading: the three curves must have the same length");
    const double peak
      = *std::max_element(axial_pressure.begin(), axial_pressure.end());
    std::vector<double> strain, axial, radial;
    for (std::size_t i = 0; i < axial_strain.size(); ++i)
      if (axial_pressure[i] >= peak / 3 && axial_pressure[i] <= 2 * peak / 3)
        {
          strain.push_back(axial_strain[i]);
          axial.push_back(axial_pressure[i]);
          radial.push_back(radial_pressure[i]);
        }
    if (strain.size() < 2)
      throw std::invalid_argument(
        "moduli_from_unloading: fewer than two points in the central third "
        "of the unloading curve; unload in more steps");
    UnloadingModuli result;
    result.axial_slope   = slope(strain, axial);
    result.lateral_slope = slope(strain, radial);
    result.points        = static_cast<unsigned int>(strain.size());
    const double M = result.axial_slope, L = result.lateral_slope;
    result.poisson_ratio  = L / (L + M);
    const double nu       = result.poisson_ratio;
    result.youngs_modulus = M * (1 + nu) * (1 - 2 * nu) / (1 - nu);
    return result;
  }
} // namespace compax::dem

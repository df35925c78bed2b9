#include "dem/analysis/fabric.h"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  double
  legendre(const unsigned int l, const double x)
  {
    const double x2 = x * x;
    switch (l)
      {
        case 0:
          return 1.0;
        case 2:
          return (3 * x2 - 1) / 2;
        case 4:
          return (35 * x2 * x2 - 30 * x2 + 3) / 8;
        case 6:
          return (231 * x2 * x2 * x2 - 315 * x2 * x2 + 105 * x2 - 5) / 16;
        case 8:
          return (6435 * x2 * x2 * x2 * x2 - 12012 * x2 * x2 * x2
                  + 6930 * x2 * x2 - 1260 * x2 + 35)
                 / 128;
        default:
          throw std::invalid_argument("legendre: l must be 0, 2, 4, 6 or 8");
      }
  }

  namespace
  {
    /// Least squares of values - 1 = sum_l c_l P_l(x) over the bins that
    /// have data; returns c20..c80.
    std::array<double, 4>
    fit_even_legendre(const std::vector<double> &x,
                      const std::vector<double> &values,
                      const std::vector<bool>   &used)
    {
      int rows = 0;
      for (const bool u : used)
        rows += u;
      if (rows < 4)
        return {0, 0, 0, 0};
      Eigen::MatrixXd A(rows, 4);
      Eigen::VectorXd rhs(rows);
      int             row = 0;
      for (std::size_t k = 0; k < x.size(); ++k)
        if (used[k])
          {
            for (unsigned int j = 0; j < 4; ++j)
              A(row, j) = legendre(2 * (j + 1), x[k]);
            rhs[row++] = values[k] - 1.0;
          }
      const Eigen::Vector4d c = A.colPivHouseholderQr().solve(rhs);
      return {c[0], c[1], c[2], c[3]};
    }
  } // namespace

  FabricSpectrum
  fit_fabric(const std::vector<Eigen::Vector3d> &normals,
             const std::vector<double>          &forces,
             const unsigned int                  bins)
  {
    if (normals.size() != forces.size() || bins < 5)
      throw std::invalid_argument(
        "fit_fabric: one force per normal and at least 5 bins");
    FabricSpectrum result;
    result.cos_theta.resize(bins);
    result.normal_density.assign(bins, 0.0);
    result.force_ratio.assign(bins, 0.0);
    std::vector<double> count(bins, 0.0);
    double              force_sum = 0.0;
    const double        width     = 1.0 / bins;
    for (std::size_t c = 0; c < normals.size(); ++c)
      {
        const double       z = std::abs(normals[c].normalized()[2]);
        const unsigned int k = std::min(bins - 1, unsigned(z / width));
        count[k] += 1;
        result.force_ratio[k] += forces[c];
        force_sum += forces[c];
      }
    const double      n     = static_cast<double>(normals.size());
    const double      f_avg = n > 0 ? force_sum / n : 0.0;
    std::vector<bool> used(bins);
    for (unsigned int k = 0; k < bins; ++k)
      {
        result.cos_theta[k] = (k + 0.5) * width;
        // Fraction in the band |cos| in bin k over its solid angle 4 pi w,
        // times 4 pi.
        result.normal_density[k] = n > 0 ? count[k] / (n * width) : 0.0;
        used[k]                  = count[k] > 0;
        result.force_ratio[k]    = used[k] && f_avg > 0
                                     ? result.force_ratio[k] / count[k] / f_avg
                                     : 0.0;
      }
    result.a = fit_even_legendre(result.cos_theta,
                                 result.normal_density,
                                 std::vector<bool>(bins, n > 0));
    result.b = fit_even_legendre(result.cos_theta, result.force_ratio, used);
    return result;
  }
} // namespace compax::dem

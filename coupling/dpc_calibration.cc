#include "coupling/dpc_calibration.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::coupling
{
  ShearLine
  shear_line_through(const StressInvariants &a, const StressInvariants &b)
  {
    if (a.p == b.p)
      throw std::domain_error(
        "shear line: the two failure states have the same pressure");
    const double slope = (b.q - a.q) / (b.p - a.p);
    return {a.q - slope * a.p, slope};
  }

  CapParameters
  cap_through_uniaxial_state(const StressInvariants &s, const ShearLine &line)
  {
    const double d = line.cohesion, t = line.tan_friction_angle;
    // g(R) = q sqrt(1 + 2.25 R^2) - d - (p - 1.5 R^2 q) tan beta grows with
    // R for q > 0 and tan beta >= 0.
    auto g = [&](const double R) {
      return s.q * std::sqrt(1.0 + 2.25 * R * R) - d
             - (s.p - 1.5 * R * R * s.q) * t;
    };
    if (!(s.q > 0.0) || !(g(0.0) < 0.0))
      throw std::domain_error(
        "cap fit: the compaction state lies on or above the shear line");
    double lo = 0.0, hi = 1.0;
    while (g(hi) < 0.0)
      {
        hi *= 2.0;
        if (hi > 1e6)
          throw std::domain_error("cap fit: no eccentricity below 1e6 fits");
      }
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it)
      {
        const double mid         = 0.5 * (lo + hi);
        (g(mid) < 0.0 ? lo : hi) = mid;
      }
    const double R   = 0.5 * (lo + hi);
    const double p_a = s.p - 1.5 * R * R * s.q;
    return {R, p_a * (1.0 + R * t) + R * d, p_a};
  }

  std::vector<double>
  cap_pressures_at_rows(const std::vector<double> &rows,
                        const std::vector<double> &rho_p,
                        const std::vector<double> &cap)
  {
    const std::size_t n = rows.size();
    if (n < 2 || rho_p.size() != n || cap.size() != n)
      throw std::domain_error("cap pressures at rows: need n >= 2 rows, one "
                              "plastic density and cap pressure each");
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b(n);
    for (std::size_t k = 0; k < n; ++k)
      {
        // DpcTable's bracket: the interval holding x, the end intervals
        // extended beyond the table.
        const auto  it = std::upper_bound(rows.begin(), rows.end(), rho_p[k]);
        std::size_t i  = it == rows.begin() ? 0 : (it - rows.begin()) - 1;
        i              = std::min(i, n - 2);
        const double w = (rho_p[k] - rows[i]) / (rows[i + 1] - rows[i]);
        A(k, i) += 1.0 - w;
        A(k, i + 1) += w;
        if (!(cap[k] > 0.0))
          throw std::domain_error("cap pressures at rows: cap pressure <= 0");
        b[k] = std::log(cap[k]);
      }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
    if (!lu.isInvertible())
      throw std::domain_error("cap pressures at rows: singular system");
    const Eigen::VectorXd y = lu.solve(b);
    std::vector<double>   out(n);
    for (std::size_t k = 0; k < n; ++k)
      out[k] = std::exp(y[k]);
    return out;
  }
} // namespace compax::coupling

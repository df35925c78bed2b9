#include "coupling/dpc_calibration.h"

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
} // namespace compax::coupling

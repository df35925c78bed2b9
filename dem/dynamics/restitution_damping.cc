#include "dem/dynamics/restitution_damping.h"

#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    struct State
    {
      double u, w;
    };

    State
    rate(const State &s, const double c)
    {
      const double u = std::max(s.u, 0.0);
      return {s.w, -u * std::sqrt(u) - c * std::sqrt(std::sqrt(u)) * s.w};
    }
  } // namespace

  double
  hertz_restitution(const double damping_ratio)
  {
    if (!(damping_ratio >= 0.0))
      throw std::invalid_argument("damping ratio must not be negative");
    const double c = 2.0 * std::sqrt(1.5) * damping_ratio;
    // The undamped contact lasts about 3.2 time units; damping shortens it.
    const double h = 3.3 / 4000.0;
    State        s{0.0, 1.0};
    for (int step = 0; step < 400000; ++step)
      {
        const State k1 = rate(s, c);
        const State k2 = rate({s.u + 0.5 * h * k1.u, s.w + 0.5 * h * k1.w}, c);
        const State k3 = rate({s.u + 0.5 * h * k2.u, s.w + 0.5 * h * k2.w}, c);
        const State k4 = rate({s.u + h * k3.u, s.w + h * k3.w}, c);
        const State next{s.u + h / 6.0 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u),
                         s.w + h / 6.0 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w)};
        if (next.u <= 0.0 && step > 0)
          {
            // Interpolate the exit velocity at u = 0 linearly in u.
            const double f = s.u / (s.u - next.u);
            return -(s.w + f * (next.w - s.w));
          }
        s = next;
      }
    return 0.0;
  }

  double
  hertz_damping_ratio(const double restitution)
  {
    if (!(restitution > 0.0 && restitution <= 1.0))
      throw std::invalid_argument("restitution must be in (0, 1]");
    if (restitution == 1.0)
      return 0.0;
    double lo = 0.0, hi = 0.5;
    while (hertz_restitution(hi) > restitution)
      hi *= 2.0;
    for (int it = 0; it < 60; ++it)
      {
        const double mid = 0.5 * (lo + hi);
        if (hertz_restitution(mid) > restitution)
          lo = mid;
        else
          hi = mid;
      }
    return 0.5 * (lo + hi);
  }
} // namespace compax::dem

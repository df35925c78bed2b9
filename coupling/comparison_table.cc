#include "coupling/comparison_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace compax::coupling
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  }

  double
  interpolate(const DensitySeries &s, const double x, const double reach)
  {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    if (n == 0 || !std::isfinite(x))
      return nan;
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) {
      return s.x[a] < s.x[b];
    });
    const double lo = s.x[order.front()], hi = s.x[order.back()];
    if (x < lo - reach || x > hi + reach)
      return nan;
    if (x < lo || x > hi)
      {
        // Within reach of an end: extend the end segment.
        if (n == 1 || lo == hi)
          return s.y[order.front()];
        const std::size_t a = x < lo ? order[0] : order[n - 2];
        const std::size_t b = x < lo ? order[1] : order[n - 1];
        return s.y[a] + (s.y[b] - s.y[a]) * (x - s.x[a]) / (s.x[b] - s.x[a]);
      }
    for (std::size_t k = 0; k < n; ++k)
      if (s.x[order[k]] == x)
        return s.y[order[k]];
    for (std::size_t k = 1; k < n; ++k)
      {
        const double x0 = s.x[order[k - 1]], x1 = s.x[order[k]];
        if (x0 < x && x < x1)
          {
            const double y0 = s.y[order[k - 1]], y1 = s.y[order[k]];
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
          }
      }
    return nan;
  }

  double
  ComparisonRow::relative_difference() const
  {
    if (!std::isfinite(value) || !std::isfinite(reference) || reference == 0.0)
      return nan;
    return (value - reference) / std::abs(reference);
  }

  std::vector<ComparisonRow>
  compare_series(const std::string   &comparison,
                 const DensitySeries &reference,
                 const DensitySeries &compared,
                 const double         reach)
  {
    std::vector<ComparisonRow> rows;
    const std::size_t n = std::min(reference.x.size(), reference.y.size());
    for (std::size_t k = 0; k < n; ++k)
      if (std::isfinite(reference.y[k]) && reference.y[k] != 0.0
          && std::isfinite(reference.x[k]))
        rows.push_back({comparison,
                        reference.x[k],
                        reference.y[k],
                        interpolate(compared, reference.x[k], reach)});
    return rows;
  }

  ComparisonSummary
  summarize(const std::vector<ComparisonRow> &rows,
            const std::string                &comparison)
  {
    ComparisonSummary s;
    for (const ComparisonRow &r : rows)
      if (r.comparison == comparison)
        {
          const double d = r.relative_difference();
          if (std::isfinite(d))
            {
              ++s.compared;
              s.sum_abs += std::abs(d);
              s.largest_abs = std::max(s.largest_abs, std::abs(d));
            }
          else
            ++s.missing;
        }
    return s;
  }
} // namespace compax::coupling

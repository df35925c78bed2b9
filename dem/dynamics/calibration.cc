#include "dem/dynamics/calibration.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace compax::dem
{
  double
  coefficient_of_determination(const std::vector<double> &y,
                               const std::vector<double> &y_hat)
  {
    if (y.size() != y_hat.size() || y.empty())
      throw std::invalid_argument("R^2: curves of different length");
    const double mean = std::accumulate(y.begin(), y.end(), 0.0)
                        / static_cast<double>(y.size());
    double residual = 0.0, total = 0.0;
    for (std::size_t k = 0; k < y.size(); ++k)
      {
        residual += (y[k] - y_hat[k]) * (y[k] - y_hat[k]);
        total += (y[k] - mean) * (y[k] - mean);
      }
    return 1.0 - residual / total;
  }

  namespace
  {
    /// Linear interpolation on one branch (points in curve order).
    double
    on_branch(const StressStrainCurve &c, const int stage, const double strain)
    {
      // The unloading branch starts at the turning point, the last
      // loading point.
      std::vector<std::pair<double, double>> points;
      for (std::size_t k = 0; k < c.strain.size(); ++k)
        if (c.stage[k] == stage
            || (stage == 2 && c.stage[k] == 1 && k + 1 < c.strain.size()
                && c.stage[k + 1] == 2))
          points.emplace_back(c.strain[k], c.stress[k]);
      if (points.empty())
        return 0.0;
      std::sort(points.begin(), points.end());
      if (strain <= points.front().first)
        return stage == 2 ? 0.0 : points.front().second;
      if (strain >= points.back().first)
        return points.back().second;
      const auto   hi = std::lower_bound(points.begin(),
                                       points.end(),
                                       std::make_pair(strain, -1e300));
      const auto   lo = hi - 1;
      const double f  = (strain - lo->first) / (hi->first - lo->first);
      return lo->second + f * (hi->second - lo->second);
    }
  } // namespace

  std::vector<double>
  simulated_at(const StressStrainCurve &measured,
               const StressStrainCurve &simulated)
  {
    std::vector<double> y(measured.strain.size());
    for (std::size_t k = 0; k < y.size(); ++k)
      y[k] = on_branch(simulated,
                       measured.stage.empty() ? 1 : measured.stage[k],
                       measured.strain[k]);
    return y;
  }

  NelderMeadResult
  nelder_mead(const std::function<double(const std::vector<double> &)> &f,
              std::vector<double>                                       x0,
              const NelderMeadOptions                                  &o)
  {
    const std::size_t n     = x0.size();
    auto              clamp = [&](std::vector<double> x) {
      for (std::size_t d = 0; d < n; ++d)
        x[d] = std::clamp(x[d], o.lower[d], o.upper[d]);
      return x;
    };
    NelderMeadResult best;
    int              evaluations = 0;
    auto             eval        = [&](const std::vector<double> &x) {
      const double v = f(x);
      ++evaluations;
      if (evaluations == 1 || v < best.f)
        {
          best.x = x;
          best.f = v;
        }
      return v;
    };
    auto done
      = [&] { return best.f <= o.target || evaluations >= o.max_evaluations; };

    std::vector<std::vector<double>> simplex{clamp(x0)};
    std::vector<double>              values{eval(simplex[0])};
    for (std::size_t d = 0; d < n && !done(); ++d)
      {
        std::vector<double> x = x0;
        x[d] += o.initial_step[d];
        if (x[d] > o.upper[d])
          x[d] = x0[d] - o.initial_step[d];
        simplex.push_back(clamp(x));
        values.push_back(eval(simplex.back()));
      }
    while (!done() && simplex.size() == n + 1)
      {
        std::vector<std::size_t> order(n + 1);
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](auto a, auto b) {
          return values[a] < values[b];
        });
        std::vector<std::vector<double>> s;
        std::vector<double>              v;
        for (const auto k : order)
          {
            s.push_back(simplex[k]);
            v.push_back(values[k]);
          }
        simplex = s;
        values  = v;
        if (std::abs(values[n] - values[0]) < o.f_tolerance)
          break;
        std::vector<double> centroid(n, 0.0);
        for (std::size_t k = 0; k < n; ++k)
          for (std::size_t d = 0; d < n; ++d)
            centroid[d] += simplex[k][d] / n;
        auto along = [&](const double t) {
          std::vector<double> x(n);
          for (std::size_t d = 0; d < n; ++d)
            x[d] = centroid[d] + t * (simplex[n][d] - centroid[d]);
          return clamp(x);
        };
        const auto   xr = along(-1.0);
        const double fr = eval(xr);
        if (fr < values[0])
          {
            if (done())
              break;
            const auto   xe = along(-2.0);
            const double fe = eval(xe);
            simplex[n]      = fe < fr ? xe : xr;
            values[n]       = std::min(fe, fr);
          }
        else if (fr < values[n - 1])
          {
            simplex[n] = xr;
            values[n]  = fr;
          }
        else
          {
            if (done())
              break;
            const auto   xc = along(fr < values[n] ? -0.5 : 0.5);
            const double fc = eval(xc);
            if (fc < std::min(fr, values[n]))
              {
                simplex[n] = xc;
                values[n]  = fc;
              }
            else
              for (std::size_t k = 1; k <= n && !done(); ++k)
                {
                  for (std::size_t d = 0; d < n; ++d)
                    simplex[k][d]
                      = simplex[0][d] + 0.5 * (simplex[k][d] - simplex[0][d]);
                  values[k] = eval(simplex[k]);
                }
          }
      }
    best.evaluations = evaluations;
    return best;
  }

  StressStrainCurve
  compaction_curve(const UniaxialCompaction                  &prepared,
                   const MulticontactAdhesiveLaw::Parameters &law,
                   const CompactionProtocol                  &protocol)
  {
    UniaxialCompaction run = prepared;
    run.dem().set_normal_law(law);
    StressStrainCurve curve;
    run.compact(protocol, [&](const CompactionRecord &r) {
      curve.strain.push_back(r.strain);
      curve.stress.push_back(r.stress_zz);
      curve.stage.push_back(r.stage);
    });
    return curve;
  }

  namespace
  {
    double *
    parameter(MulticontactAdhesiveLaw::Parameters &law, const std::string &name)
    {
      if (name == "k2/k1")
        return &law.unloading_stiffness_ratio;
      if (name == "kc/k1")
        return &law.adhesion_stiffness_ratio;
      if (name == "beta")
        return &law.multicontact_prefactor;
      throw std::invalid_argument("calibration: unknown parameter '" + name
                                  + "' (k2/k1, kc/k1, beta)");
    }
  } // namespace

  CalibrationResult
  calibrate(const StressStrainCurve                            &measured,
            const UniaxialCompaction                           &prepared,
            const MulticontactAdhesiveLaw::Parameters          &base_law,
            const CompactionProtocol                           &protocol,
            const CalibrationSpec                              &spec,
            const std::function<void(const CalibrationStep &)> &on_step)
  {
    const std::size_t n = spec.parameters.size();
    if (n == 0 || spec.initial.size() != n || spec.lower.size() != n
        || spec.upper.size() != n)
      throw std::invalid_argument(
        "calibration: one initial value and bounds per parameter");
    CalibrationResult result;
    auto              law_of = [&](const std::vector<double> &x) {
      MulticontactAdhesiveLaw::Parameters law = base_law;
      for (std::size_t d = 0; d < n; ++d)
        *parameter(law, spec.parameters[d]) = x[d];
      return law;
    };
    auto objective = [&](const std::vector<double> &x) {
      const auto   law   = law_of(x);
      const auto   curve = compaction_curve(prepared, law, protocol);
      const double r2
        = coefficient_of_determination(measured.stress,
                                       simulated_at(measured, curve));
      result.history.push_back({law, r2});
      if (r2 > result.r2)
        {
          result.r2         = r2;
          result.law        = law;
          result.best_curve = curve;
        }
      if (on_step)
        on_step(result.history.back());
      return -r2;
    };
    NelderMeadOptions options;
    options.lower           = spec.lower;
    options.upper           = spec.upper;
    options.target          = -spec.target_r2;
    options.max_evaluations = spec.max_simulations;
    for (std::size_t d = 0; d < n; ++d)
      options.initial_step.push_back(0.25 * (spec.upper[d] - spec.lower[d]));
    nelder_mead(objective, spec.initial, options);
    result.reached_target = result.r2 > spec.target_r2;
    return result;
  }
} // namespace compax::dem

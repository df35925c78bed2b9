#include "apps/mcdem/mcdem_progress.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>

namespace compax::cli
{
  void
  print_progress(const std::string &label, const dem::CompactionProgress &p)
  {
    using clock = std::chrono::steady_clock;
    // Time left extrapolated from the first report of the phase.
    static std::map<std::string, std::pair<clock::time_point, double>> first;
    const std::string key = label + p.phase;
    const auto        now = clock::now();
    if (!first.count(key))
      first[key] = {now, p.fraction};
    const auto [t0, f0]  = first[key];
    const double elapsed = std::chrono::duration<double>(now - t0).count();
    const double left    = p.fraction > f0 + 1e-3
                             ? elapsed * (1.0 - p.fraction) / (p.fraction - f0)
                             : -1.0;
    char         line[256];
    std::snprintf(
      line,
      sizeof line,
      "%s %-13s %5.1f%%  strain %.4f  stress %10.4g Pa  step "
      "%llu  left %s",
      label.c_str(),
      p.phase,
      100.0 * p.fraction,
      p.strain,
      p.stress_zz,
      static_cast<unsigned long long>(p.steps),
      left < 0 ? "?"
               : (std::to_string(static_cast<int>(left + 0.5)) + " s").c_str());
    std::cout << line << std::endl;
  }

  void
  print_summary(const std::string &label, const dem::CompactionSummary &s)
  {
    std::cout << label << " " << s.particles << " particles, packing density "
              << s.initial_density << " after growth\n"
              << label << " peak strain " << s.peak_strain << ", peak stress "
              << s.peak_stress << " Pa, residual strain " << s.residual_strain
              << "\n"
              << label << " " << s.steps << " steps in " << s.wall_seconds
              << " s: " << s.particle_steps / s.wall_seconds
              << " particle-steps/s on one core\n";
  }
} // namespace compax::cli

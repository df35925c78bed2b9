#include "dem/analysis/jamming_fit.h"

#include <exception>

namespace compax::dem
{
  std::vector<CompactionState>
  jammed_states(const std::vector<CompactionState> &states,
                const double                        pressure_resolution)
  {
    std::vector<CompactionState> jammed;
    for (const CompactionState &s : states)
      if (s.coordination_number > 0.0 && s.axial_pressure > pressure_resolution)
        jammed.push_back(s);
    return jammed;
  }

  std::optional<CoordinationFit>
  fit_jamming(const std::vector<CompactionState> &states,
              const double                        pressure_resolution)
  {
    std::vector<double> rho, Z;
    for (const CompactionState &s : jammed_states(states, pressure_resolution))
      {
        rho.push_back(s.relative_density);
        Z.push_back(s.coordination_number);
      }
    if (rho.size() < 5)
      return std::nullopt;
    try
      {
        const CoordinationFit fit = fit_coordination(rho, Z);
        // A coordination number is never negative: a power law with
        // Z_c < 0 describes the data, not a jamming point.
        if (fit.on_search_edge || fit.Z_c < 0.0)
          return std::nullopt;
        return fit;
      }
    catch (const std::exception &)
      {
        return std::nullopt;
      }
  }
} // namespace compax::dem

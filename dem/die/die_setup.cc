#include "dem/die/die_setup.h"

#include <algorithm>

namespace compax::dem
{
  Bed
  fill_die(const DepositionParameters &deposition, const double skin_fraction)
  {
    Bed bed;
    bed.particles         = ballistic_deposition(deposition);
    bed.walls.diameter    = deposition.die_diameter;
    bed.walls.lower_punch = 0.0;
    double top            = 0.0;
    for (std::size_t i = 0; i < bed.particles.size(); ++i)
      top
        = std::max(top, bed.particles.positions[i][2] + bed.particles.radii[i]);
    bed.walls.upper_punch = top;
    bed.contacts.set_skin(skin_fraction * bed.particles.mean_radius());
    return bed;
  }

  std::vector<double>
  density_targets(const double rho_start, const double rho_end, const int n)
  {
    std::vector<double> t;
    for (int k = 1; k <= n; ++k)
      t.push_back(rho_start + (rho_end - rho_start) * k / n);
    return t;
  }
} // namespace compax::dem

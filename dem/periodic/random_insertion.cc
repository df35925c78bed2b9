#include "dem/periodic/random_insertion.h"

#include "dem/numbers.h"
#include "dem/periodic/periodic_cell.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace compax::dem
{
  InsertedParticles
  insert_random(const InsertionSpec &spec, RandomSource &random)
  {
    if (!(spec.packing_density > 0.0 && spec.packing_density < 1.0))
      throw std::invalid_argument("insertion: packing density not in (0, 1)");
    InsertedParticles result;
    result.box    = spec.box;
    double volume = 0.0;
    if (spec.particle_count > 0)
      {
        for (std::size_t k = 0; k < spec.particle_count; ++k)
          {
            const double r = spec.sizes.sample(random);
            result.radii.push_back(r);
            volume += 4.0 / 3.0 * pi * r * r * r;
          }
        const double box_volume = spec.box.prod();
        result.box *= std::cbrt(volume / spec.packing_density / box_volume);
      }
    else
      {
        const double target = spec.packing_density * spec.box.prod();
        while (volume < target)
          {
            const double r = spec.sizes.sample(random);
            // Keep the sum closest to the target.
            const double v = 4.0 / 3.0 * pi * r * r * r;
            if (volume + v > target && volume + v - target > target - volume)
              break;
            result.radii.push_back(r);
            volume += v;
          }
      }
    std::sort(result.radii.begin(), result.radii.end(), std::greater<>());

    const Eigen::Vector3d L = result.box;
    const PeriodicCell    cell
      = PeriodicCell::box(L, std::array<bool, 3>{true, true, false});
    for (const double R : result.radii)
      {
        if (2.0 * R >= std::min({L[0], L[1], L[2]}))
          throw std::invalid_argument(
            "insertion: a particle is larger than the box; lower the "
            "maximum diameter or enlarge the cell");
      }
    const double s = spec.initial_scale;
    result.positions.reserve(result.radii.size());
    for (std::size_t k = 0; k < result.radii.size(); ++k)
      {
        const double    r = s * result.radii[k];
        Eigen::Vector3d best;
        double          best_gap = -1e300;
        for (int attempt = 0; attempt < 1000; ++attempt)
          {
            const Eigen::Vector3d x(random.uniform(0.0, L[0]),
                                    random.uniform(0.0, L[1]),
                                    random.uniform(r, L[2] - r));
            double                gap = 1e300;
            for (std::size_t q = 0; q < result.positions.size(); ++q)
              {
                const double dist
                  = cell.minimum_image(x - result.positions[q]).norm();
                gap = std::min(gap, dist - r - s * result.radii[q]);
              }
            if (gap > best_gap)
              {
                best_gap = gap;
                best     = x;
              }
            if (gap >= 0.0)
              break;
          }
        result.positions.push_back(best);
      }
    return result;
  }
} // namespace compax::dem

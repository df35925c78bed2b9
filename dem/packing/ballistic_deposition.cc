#include "dem/packing/ballistic_deposition.h"

#include <stdexcept>

namespace compax::dem
{
  ParticleSystem
  ballistic_deposition(const DepositionParameters &prm)
  {
    RandomSource random(prm.seed);
    const double r_max = prm.sizes.largest();
    if (2.0 * r_max >= 0.5 * prm.die_diameter)
      throw std::invalid_argument("particles do not fit into the die");
    DepositionColumn    column(prm.container, prm.die_diameter, r_max);
    std::vector<double> cumulative;
    for (const double f : prm.material_fractions)
      cumulative.push_back((cumulative.empty() ? 0.0 : cumulative.back()) + f);

    for (std::size_t n = 0; n < prm.n_particles; ++n)
      {
        const double R        = prm.sizes.sample(random);
        unsigned int material = 0;
        if (!cumulative.empty())
          {
            const double u = random.uniform() * cumulative.back();
            while (material + 1 < cumulative.size()
                   && u >= cumulative[material])
              ++material;
          }
        column.drop(column.random_start(random, R), R, material);
      }
    return std::move(column.particles);
  }
} // namespace compax::dem

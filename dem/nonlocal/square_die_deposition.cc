#include "dem/nonlocal/square_die_deposition.h"

#include "dem/packing/deposition_column.h"

#include <algorithm>
#include <stdexcept>

namespace compax::dem
{
  ParticleSystem
  square_die_deposition(const SquareDepositionParameters &prm)
  {
    if (prm.sizes.size() != prm.counts.size() || prm.sizes.empty())
      throw std::invalid_argument("one particle count per size distribution");
    double r_max = 0.0;
    for (const auto &s : prm.sizes)
      r_max = std::max(r_max, s.largest());
    if (2.0 * r_max >= prm.width)
      throw std::invalid_argument("particles do not fit into the die");

    RandomSource random(prm.seed);
    // Materials in a random order (Fisher-Yates with our own generator).
    std::vector<unsigned int> order;
    for (std::size_t m = 0; m < prm.counts.size(); ++m)
      order.insert(order.end(), prm.counts[m], static_cast<unsigned int>(m));
    for (std::size_t k = order.size(); k > 1; --k)
      {
        const auto j = static_cast<std::size_t>(random.uniform() * k);
        std::swap(order[k - 1], order[std::min(j, k - 1)]);
      }

    DepositionColumn column(DepositionContainer::square, prm.width, r_max);
    for (const unsigned int material : order)
      {
        const double R = prm.sizes[material].sample(random);
        column.drop(column.random_start(random, R), R, material);
      }
    return std::move(column.particles);
  }
} // namespace compax::dem

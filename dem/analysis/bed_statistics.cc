#include "dem/analysis/bed_statistics.h"

#include <algorithm>
#include <stdexcept>

namespace compax::dem
{
  ContactNetwork
  loaded_contacts(const Bed &bed)
  {
    ContactNetwork network;
    const auto    &p = bed.particles;
    for (const PairContact &c : bed.contacts.pairs)
      {
        const double P
          = law_response(c.law, pair_overlap(p, c), c.history).force;
        if (P == 0.0)
          continue;
        network.normals.push_back(
          (p.positions[c.i] - p.positions[c.j]).normalized());
        network.forces.push_back(P);
      }
    return network;
  }

  ForceHistogram
  force_histogram(const std::vector<double> &forces, const unsigned int bins)
  {
    if (bins == 0)
      throw std::invalid_argument("force_histogram: at least one bin");
    ForceHistogram h;
    h.centres.resize(bins);
    h.counts.assign(bins, 0);
    if (forces.empty())
      return h;
    const auto [lo, hi] = std::minmax_element(forces.begin(), forces.end());
    const double width  = (*hi > *lo ? *hi - *lo : 1.0) / bins;
    for (unsigned int k = 0; k < bins; ++k)
      h.centres[k] = *lo + (k + 0.5) * width;
    for (const double f : forces)
      ++h.counts[std::min<std::size_t>(
        bins - 1, static_cast<std::size_t>((f - *lo) / width))];
    return h;
  }
} // namespace compax::dem

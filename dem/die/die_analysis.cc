#include "dem/die/die_analysis.h"

#include "dem/analysis/unloading_moduli.h"

#include <algorithm>

namespace compax::dem
{
  BedMeasures
  measure(const Bed &bed, const double resolution)
  {
    BedMeasures m;
    std::size_t loaded = 0;
    double      ap2 = 0.0, r2 = 0.0;
    const auto &p = bed.particles;
    bed.contacts.for_each_kept_pair([&](const PairContact &c) {
      const ContactResponse r
        = law_response(c.law, pair_overlap(p, c), c.history);
      const double P = r.force;
      if (std::abs(P) > resolution)
        ++loaded;
      m.n_tensile += P < 0.0;
      m.n_compressive += P > 0.0;
      m.n_bonds += bonded(c.law, c.history);
      ap2 += bonding_area_squared(c.law, c.history, r);
    });
    for (const double R : p.radii)
      r2 += R * R;
    if (p.size() > 0)
      {
        m.coordination_number = 2.0 * loaded / p.size();
        m.bonding_surface     = ap2 / r2;
      }
    return m;
  }

  std::vector<double>
  pair_forces(const Bed &bed)
  {
    std::vector<double> f;
    for (const PairContact &c : bed.contacts.pairs)
      {
        const double P
          = law_response(c.law, pair_overlap(bed.particles, c), c.history)
              .force;
        if (P != 0.0)
          f.push_back(P);
      }
    return f;
  }

  TabletElasticity
  unloading_elasticity(const std::vector<double> &strain,
                       const std::vector<double> &axial,
                       const std::vector<double> &radial)
  {
    // moduli_from_unloading takes the compaction strain, positive when the
    // gap closes; here strain grows as the compact expands.
    std::vector<double> compression(strain.size());
    for (std::size_t i = 0; i < strain.size(); ++i)
      compression[i] = -strain[i];
    TabletElasticity t;
    try
      {
        const UnloadingModuli m
          = moduli_from_unloading(compression, axial, radial);
        t.youngs_modulus = m.youngs_modulus;
        t.poisson_ratio  = m.poisson_ratio;
        t.n_points       = static_cast<int>(m.points);
      }
    catch (const std::invalid_argument &)
      {
        // Fewer than two points in the central third: E and nu stay 0.
      }
    return t;
  }
} // namespace compax::dem

#include "dem/rve/rve_measures.h"

#include "dem/rve/periodic_assembler.h"

#include <vector>

namespace compax::dem
{
  RveMeasures
  measure_rve(const PeriodicBed &bed)
  {
    RveMeasures                                          m;
    const auto                                          &p = bed.particles;
    const std::size_t                                    n = p.size();
    std::vector<unsigned>                                loaded(n, 0);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> network;
    double                                               ap2 = 0.0, r2 = 0.0;
    for (const PeriodicContact &c : bed.contacts.pairs)
      {
        m.n_bonds += bonded(c.law, c.history);
        const double gamma
          = p.radii[c.i] + p.radii[c.j] - branch_vector(p, bed.cell, c).norm();
        if (plastic_radius(c.law, c.history) == 0.0 && gamma <= 0.0)
          continue;
        const ContactResponse r
          = periodic_contact_response(c, gamma, ContactBranch::current);
        ap2 += bonding_area_squared(c.law, c.history, r);
        if (r.force == 0.0)
          continue;
        network.emplace_back(c.i, c.j);
        ++loaded[c.i];
        ++loaded[c.j];
      }
    for (const double R : p.radii)
      r2 += R * R;
    if (n == 0)
      return m;
    m.coordination_number = 2.0 * network.size() / n;
    m.bonding_surface     = r2 > 0.0 ? ap2 / r2 : 0.0;

    // Strip rattlers until every remaining particle has 4 loaded contacts
    // with remaining particles.
    std::vector<bool> rattler(n, false);
    for (bool changed = true; changed;)
      {
        changed = false;
        for (std::size_t i = 0; i < n; ++i)
          if (!rattler[i] && loaded[i] < 4)
            {
              rattler[i] = true;
              changed    = true;
              for (const auto &[a, b] : network)
                if (a == i && !rattler[b])
                  --loaded[b];
                else if (b == i && !rattler[a])
                  --loaded[a];
            }
      }
    std::size_t kept = 0, backbone = 0;
    for (std::size_t i = 0; i < n; ++i)
      kept += !rattler[i];
    for (const auto &[a, b] : network)
      backbone += !rattler[a] && !rattler[b];
    m.rattler_fraction              = double(n - kept) / n;
    m.coordination_without_rattlers = kept ? 2.0 * backbone / kept : 0.0;
    return m;
  }
} // namespace compax::dem

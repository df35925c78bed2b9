#include "dem/crystals/crystal_compaction.h"

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  namespace
  {
    /// Onsets closer than this in epsilon are one formation event; onsets
    /// below it are contacts touching at epsilon = 0.
    constexpr double same_event = 1e-9;

    /// Whether candidate `i` carries force at deformation epsilon.
    bool
    active_at(CrystalContacts           &contacts,
              const CrystalConfiguration configuration,
              const double               preload,
              const double               epsilon,
              const std::size_t          i)
    {
      const CrystalResponse r
        = contacts.solve(crystal_cell_strains(configuration, epsilon, preload));
      return r.converged && contacts.active(i);
    }
  } // namespace

  CrystalPath
  compute_crystal_path(const CrystalConfiguration configuration,
                       const CrystalMaterial     &material,
                       const CrystalFormulation   formulation,
                       const CrystalPathOptions  &options)
  {
    const CrystalLattice lattice
      = make_crystal_lattice(configuration, material.radius);
    const unsigned int steps = std::max(1u, options.steps);

    // Smallest stretch along the path: every lattice vector longer than
    // 1.25 diameters / stretch stays 0.25 R beyond contact.
    const Eigen::Vector3d last            = crystal_cell_strains(configuration,
                                                      options.max_strain,
                                                      options.preload);
    CrystalContactOptions contact_options = options.contact;
    contact_options.neighbour_range = std::max(contact_options.neighbour_range,
                                               1.25 / (1.0 - last.maxCoeff()));
    CrystalContacts   contacts(lattice, material, formulation, contact_options);
    const std::size_t n = contacts.neighbours().size();

    CrystalPath              path;
    std::vector<double>      onset(n, std::numeric_limits<double>::quiet_NaN());
    std::vector<double>      step_force(n);
    std::vector<std::size_t> fresh;

    double previous = 0.0;
    for (unsigned int k = 0; k <= steps; ++k)
      {
        double          epsilon = options.max_strain * k / steps;
        Eigen::Vector3d strains
          = crystal_cell_strains(configuration, epsilon, options.preload);
        CrystalResponse response   = contacts.solve(strains);
        bool            last_point = false;
        if (!response.converged)
          {
            // Beyond a limit point the nonlocal formulation has no
            // solution: bracket it and end the path at the last deformation
            // solved.
            path.failure_strain = epsilon;
            if (k == 0)
              break;
            double lo = previous, hi = epsilon;
            bool   found = false;
            while (hi - lo > 1e-5 * (epsilon - previous))
              {
                const double mid = 0.5 * (lo + hi);
                if (contacts
                      .solve(crystal_cell_strains(configuration,
                                                  mid,
                                                  options.preload))
                      .converged)
                  {
                    lo    = mid;
                    found = true;
                  }
                else
                  hi = mid;
              }
            path.failure_strain = hi;
            if (!found)
              break;
            epsilon = lo;
            strains
              = crystal_cell_strains(configuration, epsilon, options.preload);
            response = contacts.solve(strains);
            if (!response.converged)
              break;
            last_point = true;
          }
        CrystalPathPoint point;
        point.strain       = epsilon;
        point.cell_strains = strains;
        point.response     = response;
        path.points.push_back(point);

        fresh.clear();
        for (std::size_t i = 0; i < n; ++i)
          if (contacts.active(i) && std::isnan(onset[i]))
            fresh.push_back(i);
        step_force = contacts.forces();
        if (k == 0)
          for (const std::size_t i : fresh)
            onset[i] = 0.0;
        else
          {
            // Symmetry-equivalent candidates have equal forces: bisect one
            // representative of each group.
            for (std::size_t a = 0; a < fresh.size(); ++a)
              {
                const std::size_t i = fresh[a];
                if (!std::isnan(onset[i]))
                  continue;
                double lo = previous, hi = epsilon;
                while (hi - lo > 1e-13 * std::max(1.0, hi))
                  {
                    const double mid = 0.5 * (lo + hi);
                    if (mid <= lo || mid >= hi)
                      break;
                    (active_at(contacts, configuration, options.preload, mid, i)
                       ? hi
                       : lo)
                      = mid;
                  }
                for (std::size_t b = a; b < fresh.size(); ++b)
                  {
                    const std::size_t j = fresh[b];
                    if (std::abs(step_force[j] - step_force[i])
                        <= 1e-9 * step_force[i])
                      onset[j] = hi > same_event ? hi : 0.0;
                  }
              }
          }
        if (last_point)
          break;
        previous = epsilon;
      }

    // Group the onsets into formation events.
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isnan(onset[i]))
        order.push_back(i);
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const std::size_t a, const std::size_t b) {
                       return onset[a] < onset[b];
                     });
    const double diameter = 2.0 * material.radius;
    for (const std::size_t i : order)
      {
        const double distance = contacts.neighbours()[i].norm() / diameter;
        if (path.formations.empty()
            || onset[i] - path.formations.back().strain > same_event)
          {
            ContactFormation f;
            f.strain           = onset[i];
            f.relative_density = lattice.relative_density(
              crystal_cell_strains(configuration, onset[i], options.preload));
            f.distance = distance;
            path.formations.push_back(f);
          }
        ContactFormation &f = path.formations.back();
        ++f.contacts;
        f.distance = std::min(f.distance, distance);
      }
    return path;
  }
} // namespace compax::dem

#include "dem/rve/rve_size_study.h"

#include "dem/rve/rve_packing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace compax::dem
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The last element of `items` that `take` accepts, or nullptr.
    template <typename T, typename Take>
    const T *
    last_of(const std::vector<T> &items, Take take)
    {
      for (auto it = items.rbegin(); it != items.rend(); ++it)
        if (take(*it))
          return &*it;
      return nullptr;
    }

    std::vector<double>
    size_quantities(const RvePathResult &path)
    {
      const auto loaded   = last_of(path.steps, [](const RvePathStep &s) {
        return !s.unloading;
      });
      const auto m_loaded = last_of(path.moduli, [](const RvePathModuli &m) {
        return !m.unloading;
      });
      const auto m_end
        = last_of(path.moduli, [](const RvePathModuli &) { return true; });
      const auto stress
        = [&](int r, int c) { return loaded ? loaded->stress(r, c) : nan; };
      return {loaded ? loaded->relative_density : nan,
              stress(0, 0),
              stress(1, 1),
              stress(2, 2),
              loaded ? -loaded->stress.trace() / 3.0 : nan,
              m_loaded ? m_loaded->isotropic.youngs_modulus : nan,
              m_loaded ? m_loaded->isotropic.poisson_ratio : nan,
              m_end ? m_end->isotropic.youngs_modulus : nan,
              m_end ? m_end->isotropic.poisson_ratio : nan};
    }
  } // namespace

  const std::vector<std::string> &
  rve_size_quantities()
  {
    static const std::vector<std::string> names{"relative_density_loaded",
                                                "sigma_xx_loaded",
                                                "sigma_yy_loaded",
                                                "sigma_zz_loaded",
                                                "mean_pressure_loaded",
                                                "E_loaded",
                                                "nu_loaded",
                                                "E_end",
                                                "nu_end"};
    return names;
  }

  RveSizeStudy::RveSizeStudy(ContactModel model, RveSizeStudyOptions options)
      : model(std::move(model))
      , options(std::move(options))
  {
  }

  PeriodicPackingSpec
  RveSizeStudy::packing(const std::size_t k) const
  {
    PeriodicPackingSpec spec = options.packing;
    spec.particle_count      = options.cell_sizes.at(k);
    spec.seed                = options.packing.seed + k;
    return spec;
  }

  RveSizeResult
  RveSizeStudy::run(const RveSizeObserver &observer) const
  {
    RveSizeResult out;
    for (std::size_t k = 0; k < options.cell_sizes.size() && out.converged; ++k)
      {
        RveSizeCell cell;
        cell.packing = packing(k);
        if (observer.packing)
          observer.packing(k, cell.packing);
        PeriodicBed bed = make_rve_packing(cell.packing,
                                           model,
                                           packing_loading(options.path));
        if (observer.packed)
          observer.packed(k, bed);
        cell.edge_over_diameter
          = std::cbrt(bed.cell.volume()) / (2.0 * bed.particles.mean_radius());
        RvePathStudy study(model, options.path, RvePathState{std::move(bed)});
        cell.path
          = study.run(observer.path ? observer.path(k) : RvePathObserver{});
        cell.quantities = size_quantities(cell.path);
        out.converged   = cell.path.converged;
        if (observer.done)
          observer.done(k, cell, study);
        out.cells.push_back(std::move(cell));
      }
    const auto &names = rve_size_quantities();
    for (std::size_t q = 0; q < names.size(); ++q)
      {
        std::vector<double> values;
        for (const RveSizeCell &cell : out.cells)
          values.push_back(cell.quantities[q]);
        out.spread.push_back(size_spread(names[q], values));
      }
    return out;
  }

  RveSizeSpread
  size_spread(const std::string &quantity, const std::vector<double> &values)
  {
    RveSizeSpread s;
    s.quantity = quantity;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0.0;
    for (const double v : values)
      if (!std::isnan(v))
        {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
          sum += v;
          ++s.count;
        }
    if (s.count == 0)
      {
        s.min = s.max = s.mean = s.spread = nan;
        return s;
      }
    s.min    = lo;
    s.max    = hi;
    s.mean   = sum / s.count;
    s.spread = s.mean != 0.0 ? (hi - lo) / std::abs(s.mean) : nan;
    return s;
  }
} // namespace compax::dem

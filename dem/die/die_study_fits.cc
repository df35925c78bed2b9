#include "dem/die/die_study_fits.h"

#include "dem/die/jamming_study.h"

#include <exception>

namespace compax::dem
{
  namespace
  {
    /// The fit of @p y against @p x, empty with fewer than @p minimum points
    /// or when the fit fails.
    template <typename Fit>
    std::optional<Fit>
    try_fit(Fit (*fit)(const std::vector<double> &,
                       const std::vector<double> &),
            const std::vector<double> &x,
            const std::vector<double> &y,
            std::size_t                minimum)
    {
      if (x.size() < minimum)
        return std::nullopt;
      try
        {
          return fit(x, y);
        }
      catch (const std::exception &)
        {
          return std::nullopt;
        }
    }
  } // namespace

  DieStudyFits
  fit_die_study(const std::vector<DieRecord>     &records,
                const std::vector<BranchSummary> &branches,
                const double                      pressure_resolution)
  {
    std::vector<double> rho, pressure;
    for (const auto &r : jammed_compaction(records, pressure_resolution))
      {
        rho.push_back(r.relative_density);
        pressure.push_back(r.upper_punch_pressure);
      }
    std::vector<double> rho_max, rho_min, recovery, residual, bonding;
    // E and nu only where the unloading curve gave them (two or more
    // points in its central third).
    std::vector<double> rho_min_E, E, nu;
    for (const auto &b : branches)
      {
        rho_max.push_back(b.rho_max_in_die);
        rho_min.push_back(b.rho_min_in_die);
        recovery.push_back(b.elastic_recovery_rho);
        residual.push_back(b.residual_radial_pressure);
        bonding.push_back(b.bonding_surface_unloaded);
        if (b.tablet.n_points >= 2)
          {
            rho_min_E.push_back(b.rho_min_in_die);
            E.push_back(b.tablet.youngs_modulus);
            nu.push_back(b.tablet.poisson_ratio);
          }
      }

    DieStudyFits fits;
    fits.jammed_states    = rho.size();
    fits.branches         = rho_max.size();
    fits.elastic_branches = rho_min_E.size();
    fits.coordination     = fit_jamming(records, pressure_resolution);
    if (fits.coordination && rho.size() >= 2)
      try
        {
          fits.punch_pressure
            = fit_punch_pressure(rho, pressure, fits.coordination->rho_c);
        }
      catch (const std::exception &)
        {
        }
    fits.elastic_recovery
      = try_fit(&fit_linear_critical, rho_max, recovery, std::size_t(2));
    fits.residual_pressure
      = try_fit(&fit_residual_pressure, rho_max, residual, std::size_t(2));
    fits.bonding_surface
      = try_fit(&fit_linear_critical, rho_min, bonding, std::size_t(2));
    fits.youngs_modulus
      = try_fit(&fit_phani_niyogi, rho_min_E, E, std::size_t(3));
    if (!nu.empty())
      {
        double sum = 0;
        for (double v : nu)
          sum += v;
        fits.poisson_ratio = sum / nu.size();
      }
    return fits;
  }
} // namespace compax::dem

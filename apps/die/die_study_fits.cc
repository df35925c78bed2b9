#include "apps/die/die_study_fits.h"

#include "dem/analysis/curve_fits.h"
#include "dem/die/jamming_study.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <string>

namespace compax::cli
{
  namespace
  {
    /// One fitted parameter: its name in fits.csv, the equation it belongs
    /// to, and its value if the study had enough points.
    struct Entry
    {
      std::string           name;
      std::string           equation;
      std::optional<double> value;
      std::size_t           points;
    };

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

    template <typename T, typename F>
    std::optional<double>
    field(const std::optional<T> &fit, F member)
    {
      if (!fit)
        return std::nullopt;
      return (*fit).*member;
    }
  } // namespace

  CompactionFits
  write_die_fits(const std::filesystem::path           &folder,
                 const std::vector<dem::DieRecord>     &records,
                 const std::vector<dem::BranchSummary> &branches,
                 const double                           pressure_resolution)
  {
    std::vector<double> rho, pressure;
    for (const auto &r : dem::jammed_compaction(records, pressure_resolution))
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

    const auto coordination = dem::fit_jamming(records, pressure_resolution);
    std::optional<dem::PunchPressureFit> punch;
    if (coordination && rho.size() >= 2)
      try
        {
          punch = dem::fit_punch_pressure(rho, pressure, coordination->rho_c);
        }
      catch (const std::exception &)
        {
        }
    const auto eps
      = try_fit(&dem::fit_linear_critical, rho_max, recovery, std::size_t(2));
    const auto res
      = try_fit(&dem::fit_residual_pressure, rho_max, residual, std::size_t(2));
    const auto bond
      = try_fit(&dem::fit_linear_critical, rho_min, bonding, std::size_t(2));
    const auto modulus
      = try_fit(&dem::fit_phani_niyogi, rho_min_E, E, std::size_t(3));
    std::optional<double> nu_mean;
    if (!nu.empty())
      {
        double sum = 0;
        for (double v : nu)
          sum += v;
        nu_mean = sum / nu.size();
      }

    using C               = dem::CoordinationFit;
    using P               = dem::PunchPressureFit;
    using L               = dem::LinearCriticalFit;
    using N               = dem::PhaniNiyogiFit;
    const std::string e14 = "(14) Z = Z_c + Z_0 (rho - rho_c_Z)^theta";
    const std::string e15 = "(15) p = K_p (rho - rho_c_Z)^beta_p";
    const std::string e17 = "(17) eps_rho = eps_0 (rho - rho_c)/(1 - rho_c)";
    const std::string e19
      = "(19) sigma_res = sigma_res_0 rho (rho - rho_c)/(1 - rho_c)";
    const std::string e23 = "(23) A_b = A_b0 (rho_min - rho_c)/(1 - rho_c)";
    const std::string e24 = "(24) E = E_0 ((rho_min - rho_c)/(1 - rho_c))^n";
    const std::vector<Entry> entries{
      {"Z_c", e14, field(coordination, &C::Z_c), rho.size()},
      {"rho_c_Z", e14, field(coordination, &C::rho_c), rho.size()},
      {"theta", e14, field(coordination, &C::theta), rho.size()},
      {"K_p", e15, field(punch, &P::K_p), rho.size()},
      {"beta_p", e15, field(punch, &P::beta_p), rho.size()},
      {"eps_0", e17, field(eps, &L::y_0), rho_max.size()},
      {"rho_c_eps", e17, field(eps, &L::rho_c), rho_max.size()},
      {"sigma_res_0", e19, field(res, &L::y_0), rho_max.size()},
      {"rho_c_e", e19, field(res, &L::rho_c), rho_max.size()},
      {"A_b0", e23, field(bond, &L::y_0), rho_min.size()},
      {"rho_c_b", e23, field(bond, &L::rho_c), rho_min.size()},
      {"E_0", e24, field(modulus, &N::E_0), rho_min_E.size()},
      {"n", e24, field(modulus, &N::n), rho_min_E.size()},
      {"rho_c_E", e24, field(modulus, &N::rho_c), rho_min_E.size()},
      {"nu_tablet", "Sec. 5.7, mean over branches", nu_mean, nu.size()}};

    std::ofstream csv(folder / "fits.csv");
    std::ofstream md(folder / "fits.md");
    csv.precision(10);
    md.precision(6);
    csv << "parameter,value\n";
    md << "| parameter | value | relation (Gonzalez 2018) | points |\n"
       << "| --- | --- | --- | --- |\n";
    for (const auto &e : entries)
      {
        csv << e.name << ',';
        md << "| " << e.name << " | ";
        if (e.value && std::isfinite(*e.value))
          {
            csv << *e.value;
            md << *e.value;
          }
        else
          md << "not determined";
        csv << '\n';
        md << " | " << e.equation << " | " << e.points << " |\n";
      }
    md << "\nSI units (K_p, sigma_res_0, E_0 in Pa). Fits need at least 5 "
          "jammed compaction steps (Eqs. 14-15), 2 unloading branches "
          "(Eqs. 17, 19, 23) and 3 branches (Eq. 24).\n";
    return {coordination, punch, eps, res, bond, modulus};
  }
} // namespace compax::cli

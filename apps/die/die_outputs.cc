#include "apps/die/die_outputs.h"

#include "apps/common/gnuplot.h"
#include "io/csv_writer.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace compax::cli
{
  namespace
  {
    /// One row per unloading branch: the densities, recoveries and
    /// pressures of Gonzalez 2018 Secs. 5.3-5.7.
    void
    write_branches(const std::filesystem::path           &file,
                   const std::vector<dem::BranchSummary> &branches)
    {
      io::CsvWriter csv(file,
                        {"branch",
                         "rho_max_in_die",
                         "rho_min_in_die",
                         "rho_tablet",
                         "max_punch_pressure",
                         "elastic_recovery_rho",
                         "elastic_recovery_H",
                         "residual_radial_pressure",
                         "ejection_pressure",
                         "coordination_compacted",
                         "bonding_surface_compacted",
                         "bonding_surface_unloaded",
                         "bonding_surface_ejected",
                         "tablet_youngs_modulus",
                         "tablet_poisson_ratio"});
      for (const auto &b : branches)
        {
          csv << b.branch << b.rho_max_in_die << b.rho_min_in_die
              << b.rho_tablet << b.max_punch_pressure << b.elastic_recovery_rho
              << b.elastic_recovery_H << b.residual_radial_pressure
              << b.ejection_pressure << b.coordination_compacted
              << b.bonding_surface_compacted << b.bonding_surface_unloaded
              << b.bonding_surface_ejected;
          // Too few points on the unloading curve: not determined.
          if (b.tablet.n_points >= 2)
            csv << b.tablet.youngs_modulus << b.tablet.poisson_ratio;
          else
            csv.empty().empty();
          csv.end_row();
        }
    }

    /// timing.csv: the wall time of every die.csv row since the run
    /// started (empty for rows taken over from a checkpoint).
    void
    write_timing(const std::filesystem::path       &file,
                 const std::vector<dem::DieRecord> &rows,
                 const std::size_t                  taken_over)
    {
      io::CsvWriter csv(file, {"stage", "branch", "step", "wall_seconds"});
      for (std::size_t k = 0; k < rows.size(); ++k)
        {
          csv << rows[k].stage << rows[k].branch << rows[k].step;
          if (k < taken_over)
            csv.empty();
          else
            csv << rows[k].wall_seconds;
          csv.end_row();
        }
    }

    /// One fitted parameter: its name in fits.csv, the equation it belongs
    /// to, and its value if the study had enough points.
    struct FitEntry
    {
      std::string           name;
      std::string           equation;
      std::optional<double> value;
      std::size_t           points;
    };

    template <typename T, typename F>
    std::optional<double>
    field(const std::optional<T> &fit, F member)
    {
      if (!fit)
        return std::nullopt;
      return (*fit).*member;
    }

    /// fits.csv and fits.md.
    void
    write_fits(const std::filesystem::path &folder,
               const dem::DieStudyFits     &fits)
    {
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
      const std::size_t jammed = fits.jammed_states, branches = fits.branches,
                        elastic = fits.elastic_branches;
      const std::vector<FitEntry> entries{
        {"Z_c", e14, field(fits.coordination, &C::Z_c), jammed},
        {"rho_c_Z", e14, field(fits.coordination, &C::rho_c), jammed},
        {"theta", e14, field(fits.coordination, &C::theta), jammed},
        {"K_p", e15, field(fits.punch_pressure, &P::K_p), jammed},
        {"beta_p", e15, field(fits.punch_pressure, &P::beta_p), jammed},
        {"eps_0", e17, field(fits.elastic_recovery, &L::y_0), branches},
        {"rho_c_eps", e17, field(fits.elastic_recovery, &L::rho_c), branches},
        {"sigma_res_0", e19, field(fits.residual_pressure, &L::y_0), branches},
        {"rho_c_e", e19, field(fits.residual_pressure, &L::rho_c), branches},
        {"A_b0", e23, field(fits.bonding_surface, &L::y_0), branches},
        {"rho_c_b", e23, field(fits.bonding_surface, &L::rho_c), branches},
        {"E_0", e24, field(fits.youngs_modulus, &N::E_0), elastic},
        {"n", e24, field(fits.youngs_modulus, &N::n), elastic},
        {"rho_c_E", e24, field(fits.youngs_modulus, &N::rho_c), elastic},
        {"nu_tablet",
         "Sec. 5.7, mean over branches",
         fits.poisson_ratio,
         elastic}};

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
    }

    /// Punch and die-wall pressure, and Z, against in-die density, with the
    /// fits of Eqs. (14) and (15) where the study determined them.
    void
    plot(const std::filesystem::path &folder, const dem::DieStudyFits &fits)
    {
      std::ostringstream functions, pressure_fit, coordination_fit;
      functions.precision(10);
      if (fits.punch_pressure && fits.coordination)
        {
          functions << "Kp = " << fits.punch_pressure->K_p
                    << "; bp = " << fits.punch_pressure->beta_p
                    << "; rcp = " << fits.coordination->rho_c << "\n"
                    << "p(x) = x > rcp ? Kp * (x - rcp)**bp / 1e6 : 1/0\n";
          pressure_fit << ", p(x) with lines dt 2 lw 2 title 'Eq. (15) fit'";
        }
      if (fits.coordination)
        {
          functions << "Zc = " << fits.coordination->Z_c
                    << "; Z0 = " << fits.coordination->Z_0
                    << "; rcz = " << fits.coordination->rho_c
                    << "; th = " << fits.coordination->theta << "\n"
                    << "z(x) = x > rcz ? Zc + Z0 * (x - rcz)**th : 1/0\n";
          coordination_fit
            << ", z(x) with lines dt 2 lw 2 title 'Eq. (14) fit'";
        }
      render_png(folder,
                 "die.gp",
                 "set datafile columnheaders\n" + functions.str()
                   + "set samples 400\n"
                     "set multiplot layout 1,2\n"
                     "set xlabel 'in-die relative density [-]'\n"
                     "set ylabel 'pressure [MPa]'\n"
                     "plot 'die.csv' using (column('relative_density')):"
                     "(column('upper_punch_pressure')/1e6) with linespoints "
                     "pt 7 ps 0.4 title 'upper punch', '' using "
                     "(column('relative_density')):(column('die_wall_pressure')"
                     "/1e6) with linespoints pt 7 ps 0.4 title 'die wall'"
                   + pressure_fit.str()
                   + "\n"
                     "set ylabel 'mean coordination number Z [-]'\n"
                     "plot 'die.csv' using (column('relative_density')):"
                     "(column('coordination_number')) with points pt 7 ps "
                     "0.5 title 'Z'"
                   + coordination_fit.str() + "\nunset multiplot\n",
                 "die.png");
    }

    /// Gnuplot text of a fitted parameter, or a value that hides the curve.
    template <typename T>
    std::string
    value(const std::optional<T> &fit, double T::*member)
    {
      std::ostringstream s;
      s.precision(12);
      if (fit && std::isfinite((*fit).*member))
        s << (*fit).*member;
      else
        s << "NaN";
      return s.str();
    }

    /**
     * branches.png: the results per unloading branch against their fits
     * (Gonzalez 2018 Secs. 5.3-5.7): elastic recovery eps_rho and residual
     * radial pressure against rho_max (Eqs. 17, 19), the bonding surface
     * after unloading and the tablet's Young's modulus against rho_min
     * (Eqs. 23, 24). Curves without a fit are left out.
     */
    void
    plot_branches(const std::filesystem::path &folder,
                  const dem::DieStudyFits     &fits)
    {
      using L = dem::LinearCriticalFit;
      using N = dem::PhaniNiyogiFit;
      std::ostringstream s;
      s << "set datafile columnheaders\nset datafile separator ','\n"
        << "e0 = " << value(fits.elastic_recovery, &L::y_0)
        << "; rce = " << value(fits.elastic_recovery, &L::rho_c) << "\n"
        << "s0 = " << value(fits.residual_pressure, &L::y_0)
        << "; rcs = " << value(fits.residual_pressure, &L::rho_c) << "\n"
        << "a0 = " << value(fits.bonding_surface, &L::y_0)
        << "; rcb = " << value(fits.bonding_surface, &L::rho_c) << "\n"
        << "E0 = " << value(fits.youngs_modulus, &N::E_0)
        << "; nE = " << value(fits.youngs_modulus, &N::n)
        << "; rcE = " << value(fits.youngs_modulus, &N::rho_c) << "\n"
        << "eps(x) = e0 * (x - rce) / (1 - rce)\n"
        << "sres(x) = s0 * x * (x - rcs) / (1 - rcs) / 1e6\n"
        << "ab(x) = a0 * (x - rcb) / (1 - rcb)\n"
        << "emod(x) = x > rcE ? E0 * ((x - rcE) / (1 - rcE))**nE / 1e9 : "
           "1/0\n"
        << "set samples 300\nset key top left\n"
        << "set multiplot layout 2,2\n"
        << "set xlabel 'rho_{max} (in-die) [-]'\n"
        << "set ylabel 'elastic recovery {/Symbol e}_{/Symbol r} [%]'\n"
        << "plot 'branches.csv' using 'rho_max_in_die':"
           "(100*column('elastic_recovery_rho')) with points pt 7 "
           "title 'simulation'"
        << (fits.elastic_recovery
              ? ", 100*eps(x) with lines dt 2 lw 2 title 'Eq. (17) fit'"
              : "")
        << "\nset ylabel 'residual radial pressure [MPa]'\n"
        << "plot 'branches.csv' using 'rho_max_in_die':"
           "(column('residual_radial_pressure')/1e6) with points pt 7 "
           "title 'simulation'"
        << (fits.residual_pressure
              ? ", sres(x) with lines dt 2 lw 2 title 'Eq. (19) fit'"
              : "")
        << "\nset xlabel 'rho_{min} (in-die, unloaded) [-]'\n"
        << "set ylabel 'bonding surface A_b [-]'\n"
        << "plot 'branches.csv' using 'rho_min_in_die':"
           "'bonding_surface_unloaded' with points pt 7 title 'simulation'"
        << (fits.bonding_surface
              ? ", ab(x) with lines dt 2 lw 2 title 'Eq. (23) fit'"
              : "")
        << "\nset ylabel 'tablet Young''s modulus [GPa]'\n"
        << "plot 'branches.csv' using 'rho_min_in_die':"
           "(column('tablet_youngs_modulus')/1e9) with points pt 7 "
           "title 'simulation'"
        << (fits.youngs_modulus
              ? ", emod(x) with lines dt 2 lw 2 title 'Eq. (24) fit'"
              : "")
        << "\nunset multiplot\n";
      render_png(folder, "branches.gp", s.str(), "branches.png");
    }

  } // namespace

  void
  write_die_outputs(const std::filesystem::path &folder,
                    const dem::DieStudyResult   &result)
  {
    write_timing(folder / "timing.csv", result.rows, result.taken_over);
    write_branches(folder / "branches.csv", result.branches);
    write_fits(folder, result.fits);
    plot(folder, result.fits);
    if (!result.branches.empty())
      plot_branches(folder, result.fits);
  }
} // namespace compax::cli

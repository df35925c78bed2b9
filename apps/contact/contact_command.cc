#include "apps/contact/contact_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/gnuplot.h"
#include "apps/contact/contact_pair.h"
#include "apps/contact/overlap_path.h"
#include "coupling/parameters/material_parameters.h"
#include "io/csv_writer.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace compax::cli
{
  namespace
  {
    /// The Du et al. (2008) sphere of Gonzalez 2018, Sec. 3.3.
    constexpr coupling::ParticleDefaults du_sphere{1.3e-6,
                                                   233e9,
                                                   0.3,
                                                   12.1e9,
                                                   1.79,
                                                   0};

    /// Extremes of a force history, as printed at the end of a run.
    struct ForceSummary
    {
      double peak_force      = 0.0;
      double peak_gamma      = 0.0;
      double pull_off_force  = 0.0;
      double pull_off_gamma  = std::numeric_limits<double>::quiet_NaN();
      double pull_off_radius = 0.0;
      double breakage_gamma  = std::numeric_limits<double>::quiet_NaN();
    };

    class ContactCommand : public Command
    {
    public:
      ContactCommand()
          : Command(
            {"contact",
             "one contact pair along a prescribed overlap history",
             "Evaluates one contact law (hertz, bonded-elastoplastic, "
             "...) for a sphere-sphere or sphere-wall pair along a "
             "piecewise-linear history of the overlap gamma (load, "
             "unload, reload, unload past breakage, any number of "
             "segments), updating the internal variables after every "
             "step as a converged state.\n\nWrites contact.csv "
             "(step,gamma,force,contact_radius, the law's internal "
             "variables (a_p,a_B of the bonded law, delta_max of the "
             "hysteretic ones), stiffness; SI units), contact.png (force "
             "and contact radius against gamma, like Gonzalez 2018 Figs. 4 "
             "and 7) with its gnuplot "
             "script, and prints the peak compressive force, the pull-off "
             "force with its gamma and contact radius, and the gamma at "
             "which the bond breaks.\n\nBuilt-in default: the Du et al. "
             "case of Gonzalez 2018 Sec. 3.3, a sphere of R = 1.3 um on a "
             "rigid flat (E = 233 GPa, nu = 0.3, kappa = 12.1 GPa, m = "
             "1.79, K_Ic = 0.48 MPa m^1/2, xi_B = 0.01) loaded to "
             "gamma_max = 28.2 nm, then unloaded past breakage."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_contact_pair(prm, du_sphere);
        declare_overlap_path(prm, "0, 28.2e-9, 14e-9");
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        make_contact_pair(prm);
        get_overlap_path(prm);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const ContactPair                       pair = make_contact_pair(prm);
        const std::vector<double>               path = get_overlap_path(prm);
        const std::vector<dem::HistoryVariable> variables
          = pair.law->history_variables();
        std::vector<std::string> columns{"step",
                                         "gamma",
                                         "force",
                                         "contact_radius"};
        for (const dem::HistoryVariable &v : variables)
          columns.emplace_back(v.symbol);
        columns.emplace_back("stiffness");
        io::CsvWriter       csv(folder / "contact.csv", columns);
        ForceSummary        summary;
        dem::ContactHistory history;
        for (std::size_t step = 0; step < path.size(); ++step)
          {
            const double gamma   = path[step];
            const auto   context = pair.context(gamma);
            const auto   r       = pair.law->evaluate(gamma, history, context);
            const auto   next
              = pair.law->updated_history(gamma, history, context);
            if (pair.law->bonded(history) && !pair.law->bonded(next)
                && std::isnan(summary.breakage_gamma))
              summary.breakage_gamma = gamma;
            history = next;

            csv << static_cast<long long>(step) << gamma << r.force
                << r.contact_radius;
            for (std::size_t v = 0; v < variables.size(); ++v)
              csv << history[v];
            csv << r.stiffness;
            csv.end_row();

            if (r.force > summary.peak_force)
              {
                summary.peak_force = r.force;
                summary.peak_gamma = gamma;
              }
            if (r.force < summary.pull_off_force)
              {
                summary.pull_off_force  = r.force;
                summary.pull_off_gamma  = gamma;
                summary.pull_off_radius = r.contact_radius;
              }
          }
        csv.close();
        print_summary(pair,
                      summary,
                      *std::max_element(path.begin(), path.end()));
        plot(folder, variables);
        return success;
      }

    private:
      static void
      print_summary(const ContactPair  &pair,
                    const ForceSummary &s,
                    const double        gamma_max)
      {
        std::cout << "Contact law " << pair.law->name() << " (" << pair.geometry
                  << ")\n"
                  << "  peak compressive force   " << s.peak_force
                  << " N at gamma = " << s.peak_gamma << " m\n";
        if (s.pull_off_force < 0.0)
          std::cout << "  pull-off (most tensile)  " << s.pull_off_force
                    << " N at gamma = " << s.pull_off_gamma
                    << " m, contact radius " << s.pull_off_radius << " m\n";
        else
          std::cout << "  pull-off (most tensile)  none: the force never "
                       "became tensile\n";
        if (!std::isnan(s.breakage_gamma))
          std::cout << "  bond broken at gamma     " << s.breakage_gamma
                    << " m (first step with a = 0)\n";
        else
          std::cout << "  bond broken at gamma     not reached\n";
        for (const auto &line : pair.closed_forms(gamma_max))
          std::cout << "  " << line << '\n';
      }

      /// contact.png: P(gamma), and a(gamma) with the law's internal
      /// variables that are lengths (columns 5, 6, ... of contact.csv).
      static void
      plot(const std::filesystem::path             &folder,
           const std::vector<dem::HistoryVariable> &variables)
      {
        std::string radii = "plot 'contact.csv' using 2:4 with lines lw 2 "
                            "title 'a(gamma)'";
        for (std::size_t v = 0; v < variables.size(); ++v)
          if (std::string(variables[v].unit) == "m")
            radii += ", '' using 2:" + std::to_string(5 + v) + " with lines dt "
                     + std::to_string(2 + v) + " title '" + variables[v].symbol
                     + "'";
        render_png(folder,
                   "contact.gp",
                   "set multiplot layout 2,1\n"
                   "set xlabel 'overlap gamma [m]'\n"
                   "set ylabel 'force P [N]'\n"
                   "plot 'contact.csv' using 2:3 with lines lw 2 "
                   "title 'P(gamma)'\n"
                   "set ylabel 'contact radius a [m]'\n"
                     + radii + "\nunset multiplot\n",
                   "contact.png");
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_contact_command()
  {
    return std::make_unique<ContactCommand>();
  }
} // namespace compax::cli

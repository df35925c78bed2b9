#include "apps/mcdem/mcdem_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/gnuplot.h"
#include "apps/mcdem/mcdem_parameters.h"
#include "apps/mcdem/mcdem_progress.h"
#include "io/csv_writer.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    const std::vector<std::string> columns{"time",
                                           "stage",
                                           "strain",
                                           "stress_zz",
                                           "stress_zz_bulk",
                                           "relative_density",
                                           "kinetic_energy",
                                           "elastic_energy",
                                           "coordination_number",
                                           "mean_particle_pressure",
                                           "time_step",
                                           "cell_size"};

    void
    write_row(io::CsvWriter               &csv,
              const dem::CompactionRecord &r,
              const double                 L)
    {
      csv << r.time << r.stage << r.strain << r.stress_zz << r.stress_zz_bulk
          << r.relative_density << r.kinetic_energy << r.elastic_energy
          << r.coordination << r.mean_pressure << r.time_step << L;
      csv.end_row();
    }

    class McdemCommand : public Command
    {
    public:
      McdemCommand()
          : Command(
            {"mcdem",
             "explicit multi-contact DEM compaction of a periodic RVE "
             "(Giannis 2021)",
             "Explicit DEM (velocity Verlet, Hertz-Mindlin with dashpots "
             "from the coefficient of restitution, Coulomb friction, "
             "constant directional rolling torque) with the adhesive "
             "elasto-plastic multi-contact normal law of Giannis et al. "
             "2021, Eqs. (6)-(14): each particle's stress tensor from its "
             "contact forces feeds the pressure term of the next step. "
             "Particles drawn from a log-normal fitted to x10, x50, x90 "
             "(Table 1) are inserted at random in a cube periodic in x and "
             "y between two plates, grown to the packing density, then "
             "compacted by the top plate at a constant strain rate to a "
             "target strain or stress and decompressed until the plate "
             "stress vanishes. Several cell sizes run the RVE-size study "
             "of Sec. 4.1.\n\nWrites mcdem.csv (time [s], stage 1 "
             "compression / 2 decompression, strain, stress_zz [Pa, plate "
             "stress, compression positive], stress_zz_bulk [Pa, Love-Weber "
             "of the particles], relative_density [sum of particle volumes "
             "/ cell volume], kinetic_energy and elastic_energy [J], "
             "coordination_number, mean_particle_pressure [Pa], time_step "
             "[s], cell_size [m]), mcdem.png with its gnuplot script, and "
             "for several cell sizes mcdem_cell_<k>.csv and rve_study.csv; "
             "prints progress and the throughput in particle-steps per "
             "second.\n\nBuilt-in default: MCC-A (Tables 1-3: E = 258 MPa, "
             "k2/k1 = 120, kc/k1 = 0.5, phi_f = 0.99, beta = 1.3) in a "
             "0.6 mm cell (about 70 particles) compacted to 57% strain at "
             "50 1/s with mass scaling 10, and unloaded; a few seconds."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_mcdem_parameters(prm, 10.0, 50.0);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        get_mcdem_setup(prm);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        McdemSetup setup = get_mcdem_setup(prm);
        std::cout << "Size distribution: volume log-normal fitted to x10, "
                     "x50, x90: median "
                  << setup.fitted_median_diameter << " m, sigma "
                  << setup.fitted_log_sigma << "\n";
        const std::size_t              n_sizes = setup.cell_sizes.size();
        std::vector<double>            cell_edges;
        io::CsvWriter                  csv(folder / "mcdem.csv", columns);
        std::unique_ptr<io::CsvWriter> study;
        if (n_sizes > 1)
          study = std::make_unique<io::CsvWriter>(
            folder / "rve_study.csv",
            std::vector<std::string>{"cell_size",
                                     "particles",
                                     "initial_density",
                                     "peak_strain",
                                     "peak_stress",
                                     "stress_at_half_peak_strain",
                                     "residual_strain",
                                     "steps"});
        std::unique_ptr<io::CsvWriter> timing;
        if (n_sizes > 1)
          timing = std::make_unique<io::CsvWriter>(
            folder / "timing.csv",
            std::vector<std::string>{"cell_size", "wall_seconds"});
        for (std::size_t k = 0; k < n_sizes; ++k)
          {
            dem::RveSpec rve = setup.rve;
            rve.cell_size    = setup.cell_sizes[k];
            std::ostringstream label;
            if (rve.particle_count > 0)
              label << "[" << rve.particle_count << " particles]";
            else
              label << "[cell " << rve.cell_size * 1e3 << " mm]";
            dem::UniaxialCompaction run(setup.material, setup.settings, rve);
            auto progress = [&](const dem::CompactionProgress &p) {
              print_progress(label.str(), p);
            };
            run.prepare(setup.protocol, progress);
            const double L = run.box()[0];
            cell_edges.push_back(L);
            std::cout << label.str() << " " << run.dem().particles().size()
                      << " particles in a " << L << " m cube\n";
            std::unique_ptr<io::CsvWriter> own;
            if (n_sizes > 1)
              own = std::make_unique<io::CsvWriter>(
                folder / ("mcdem_cell_" + std::to_string(k + 1) + ".csv"),
                columns);
            std::vector<std::pair<double, double>> loading;
            const auto                             summary = run.compact(
              setup.protocol,
              [&](const dem::CompactionRecord &r) {
                write_row(csv, r, L);
                if (own)
                  write_row(*own, r, L);
                if (r.stage == 1)
                  loading.emplace_back(r.strain, r.stress_zz);
              },
              progress);
            if (own)
              own->close();
            print_summary(label.str(), summary);
            if (study)
              {
                double half = 0.0;
                for (const auto &[e, s] : loading)
                  if (e <= 0.5 * summary.peak_strain)
                    half = s;
                *study << L << static_cast<long long>(summary.particles)
                       << summary.initial_density << summary.peak_strain
                       << summary.peak_stress << half << summary.residual_strain
                       << static_cast<long long>(summary.steps);
                study->end_row();
                *timing << L << summary.wall_seconds;
                timing->end_row();
              }
          }
        csv.close();
        if (study)
          study->close();
        plot(folder, cell_edges);
        return success;
      }

    private:
      static void
      plot(const std::filesystem::path &folder,
           const std::vector<double>   &sizes)
      {
        const std::size_t  n_sizes = sizes.size();
        std::ostringstream s;
        s << "set datafile separator ','\n"
             "set multiplot layout 1,2\n"
             "set xlabel 'strain [-]'\nset ylabel 'axial stress {/Symbol "
             "s}_{zz} [MPa]'\n"
             "set key top left\n";
        if (n_sizes == 1)
          s << "plot 'mcdem.csv' using 3:($4/1e6) every ::1 with lines lw 2 "
               "title 'plates', '' using 3:($5/1e6) every ::1 with lines dt "
               "2 title 'Love-Weber'\n";
        else
          {
            s << "plot ";
            for (std::size_t k = 1; k <= n_sizes; ++k)
              s << (k > 1 ? ", " : "") << "'mcdem_cell_" << k
                << ".csv' using 3:($4/1e6) every ::1 with lines lw 2 title '"
                << sizes[k - 1] * 1e3 << " mm'";
            s << "\n";
          }
        s << "set ylabel 'relative density [-]'\n"
             "plot 'mcdem.csv' using 3:6 every ::1 with points pt 7 ps 0.4 "
             "title 'sum V_i / V'\n"
             "unset multiplot\n";
        render_png(folder, "mcdem.gp", s.str(), "mcdem.png");
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_mcdem_command()
  {
    return std::make_unique<McdemCommand>();
  }
} // namespace compax::cli

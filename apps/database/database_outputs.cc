#include "apps/database/database_outputs.h"

#include "apps/common/gnuplot.h"
#include "coupling/parameters/voigt_columns.h"
#include "dem/rve/homogenization.h"
#include "io/csv_writer.h"

namespace compax::cli
{
  void
  write_database_rows(const std::filesystem::path &folder,
                      const coupling::RveDatabase &db)
  {
    std::vector<std::string> columns{"branch",
                                     "path",
                                     "relative_density",
                                     "shear_strain"};
    for (const char *tensor : {"eps", "sigma"})
      for (std::string &column : coupling::voigt_columns(tensor))
        columns.push_back(std::move(column));
    columns.insert(columns.end(), {"p", "q"});
    io::CsvWriter csv(folder / "database.csv", std::move(columns));
    for (const coupling::DatabaseRow &r : db.rows)
      {
        csv << r.branch << r.path << r.relative_density << r.shear_strain;
        const dem::Vector6d eps
          = dem::to_voigt(dem::logarithmic_strain(r.deformation));
        for (int k = 0; k < 6; ++k)
          csv << eps[k];
        for (int k = 0; k < 6; ++k)
          csv << r.stress[k];
        const coupling::StressInvariants s = coupling::invariants(r.stress);
        csv << s.p << s.q;
        csv.end_row();
      }
    csv.close();
  }

  void
  write_dpc_table(const std::filesystem::path            &folder,
                  const std::vector<coupling::DpcFitRow> &rows)
  {
    io::CsvWriter csv(folder / "dpc_table.csv", fem::DpcTable::columns());
    for (const coupling::DpcFitRow &r : rows)
      {
        csv << r.relative_density << r.cohesion << r.friction_angle_deg
            << r.cap_eccentricity << r.cap_pressure << r.youngs_modulus
            << r.poisson_ratio;
        csv.end_row();
      }
    csv.close();
    const std::string script
      = "set datafile separator ','\n"
        "set terminal pngcairo size 1200,800\n"
        "set output 'dpc_table.png'\n"
        "set multiplot layout 2,3\n"
        "set xlabel 'relative density'\n"
        "set key off\n"
        "set title 'cohesion d [MPa]'\n"
        "plot 'dpc_table.csv' every ::1 using 1:($2/1e6) with linespoints\n"
        "set title 'friction angle [deg]'\n"
        "plot 'dpc_table.csv' every ::1 using 1:3 with linespoints\n"
        "set title 'cap eccentricity R'\n"
        "plot 'dpc_table.csv' every ::1 using 1:4 with linespoints\n"
        "set title 'cap pressure p_b [MPa]'\n"
        "plot 'dpc_table.csv' every ::1 using 1:($5/1e6) with linespoints\n"
        "set title 'E [GPa]'\n"
        "plot 'dpc_table.csv' every ::1 using 1:($6/1e9) with linespoints\n"
        "set title 'Poisson ratio'\n"
        "plot 'dpc_table.csv' every ::1 using 1:7 with linespoints\n"
        "unset multiplot\n";
    render_png(folder, "dpc_table.gp", script, "dpc_table.png");
  }

  void
  write_branches(const std::filesystem::path            &folder,
                 const coupling::RveDatabase            &db,
                 const std::vector<coupling::DpcFitRow> &fit)
  {
    io::CsvWriter branches(folder / "branches.csv",
                           {"relative_density",
                            "unloaded_density",
                            "youngs_modulus",
                            "poisson_ratio",
                            "shear_p",
                            "shear_q",
                            "confined_shear_p",
                            "confined_shear_q",
                            "plastic_density",
                            "fitted_cap_pressure"});
    for (std::size_t k = 0; k < db.branches.size(); ++k)
      {
        const coupling::DatabaseBranch &b = db.branches[k];
        branches << b.relative_density << b.unloaded_density
                 << b.elastic.youngs_modulus << b.elastic.poisson_ratio
                 << b.shear_failure.p << b.shear_failure.q
                 << b.confined_shear_failure.p << b.confined_shear_failure.q;
        if (k < fit.size())
          branches << fit[k].plastic_density << fit[k].fitted_cap_pressure;
        else
          branches << std::string() << std::string();
        branches.end_row();
      }
    branches.close();
  }

  void
  write_validation(const std::filesystem::path                     &folder,
                   const std::vector<coupling::DatabaseComparison> &comparisons)
  {
    io::CsvWriter csv(folder / "validation.csv",
                      {"comparison",
                       "branch",
                       "path",
                       "role",
                       "relative_density",
                       "points",
                       "stress_error",
                       "p_error",
                       "q_error"});
    for (const coupling::DatabaseComparison &comparison : comparisons)
      for (const coupling::PathError &e : comparison.errors)
        {
          csv << comparison.name << e.branch << e.path
              << std::string(e.training ? "training" : "held_out")
              << e.relative_density << static_cast<int>(e.points)
              << e.stress_error << e.p_error << e.q_error;
          csv.end_row();
        }
    csv.close();
  }

  void
  write_validation_rows(const std::filesystem::path &folder,
                        const coupling::RveDatabase &rve,
                        const coupling::RveDatabase &law)
  {
    io::CsvWriter csv(folder / "validation_rows.csv",
                      {"row",
                       "branch",
                       "path",
                       "relative_density",
                       "p_rve",
                       "q_rve",
                       "p_law",
                       "q_law",
                       "sigma_xx_rve",
                       "sigma_xx_law",
                       "sigma_zz_rve",
                       "sigma_zz_law",
                       "sigma_xz_rve",
                       "sigma_xz_law"});
    for (std::size_t r = 0; r < rve.rows.size(); ++r)
      {
        const auto &a = rve.rows[r], &b = law.rows[r];
        const auto  ia = coupling::invariants(a.stress);
        const auto  ib = coupling::invariants(b.stress);
        csv << static_cast<int>(r) << a.branch << a.path << a.relative_density
            << ia.p << ia.q << ib.p << ib.q << a.stress[0] << b.stress[0]
            << a.stress[2] << b.stress[2] << a.stress[4] << b.stress[4];
        csv.end_row();
      }
    csv.close();
  }

  void
  plot_validation(const std::filesystem::path &folder)
  {
    const std::string script
      = "set datafile separator ','\n"
        "set multiplot layout 2,1\n"
        "set xlabel 'database row (compaction path, then per branch: "
        "unloading, shear, confinement, confined shear, radial probes)'\n"
        "set key top left\n"
        "set ylabel 'p [MPa]'\n"
        "plot 'validation_rows.csv' every ::1 using 1:($5/1e6) with points "
        "pt 7 ps 0.5 title 'RVE', '' every ::1 using 1:($7/1e6) with "
        "points pt 6 ps 0.6 title 'fitted DPC'\n"
        "set ylabel 'q [MPa]'\n"
        "plot 'validation_rows.csv' every ::1 using 1:($6/1e6) with points "
        "pt 7 ps 0.5 title 'RVE', '' every ::1 using 1:($8/1e6) with "
        "points pt 6 ps 0.6 title 'fitted DPC'\n"
        "unset multiplot\n";
    render_png(folder, "validation.gp", script, "validation.png");
  }
} // namespace compax::cli

#include "apps/database/database_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/common/gnuplot.h"
#include "apps/rve/rve_parameters.h"
#include "coupling/hdf5_archive.h"
#include "coupling/rve_database.h"
#include "fem/dpc_table.h"

#include <deal.II/base/utilities.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    /// The study read from the parameters.
    struct DatabaseStudy
    {
      RveCell                cell;
      coupling::DatabaseSpec spec;
    };

    DatabaseStudy
    read_study(dealii::ParameterHandler &prm)
    {
      DatabaseStudy study{get_rve_cell(prm), {}};
      auto         &spec = study.spec;
      spec.packing       = study.cell.packing;
      spec.loading       = get_rve_loading_options(prm);
      prm.enter_subsection("Paths");
      spec.final_density      = prm.get_double("Final relative density");
      spec.strain_step        = prm.get_double("Compaction strain step");
      spec.branch_densities   = get_real_list(prm, "Branch densities");
      spec.shear_strain       = prm.get_double("Shear strain");
      spec.shear_steps        = prm.get_integer("Shear steps");
      spec.confinement_strain = prm.get_double("Confinement strain");
      prm.leave_subsection();

      const std::string list = prm.get("Paths/Branch densities");
      if (spec.branch_densities.size() < 2)
        reject_entry("Paths/Branch densities",
                     list,
                     "a density-dependent cap needs at least two branches");
      for (std::size_t k = 0; k < spec.branch_densities.size(); ++k)
        {
          const double rho = spec.branch_densities[k];
          if (!(rho > spec.packing.relative_density
                && rho <= spec.final_density)
              || (k > 0 && !(rho > spec.branch_densities[k - 1])))
            reject_entry("Paths/Branch densities",
                         list,
                         "increasing densities in (Packing/Initial relative "
                         "density, Paths/Final relative density] = ("
                           + format_number(spec.packing.relative_density) + ", "
                           + format_number(spec.final_density) + "]");
        }
      return study;
    }

    void
    write_rows(const std::filesystem::path &folder,
               const coupling::RveDatabase &db)
    {
      CsvWriter csv(folder / "database.csv",
                    {"branch",
                     "path",
                     "relative_density",
                     "shear_strain",
                     "sigma_xx",
                     "sigma_yy",
                     "sigma_zz",
                     "sigma_yz",
                     "sigma_xz",
                     "sigma_xy",
                     "p",
                     "q"});
      for (const coupling::DatabaseRow &r : db.rows)
        {
          csv << r.branch << r.path << r.relative_density << r.shear_strain;
          for (int k = 0; k < 6; ++k)
            csv << r.stress[k];
          const coupling::StressInvariants s = coupling::invariants(r.stress);
          csv << s.p << s.q;
          csv.end_row();
        }
      csv.close();
    }

    void
    write_archive(const std::filesystem::path &folder,
                  const coupling::RveDatabase &db)
    {
      coupling::Hdf5ArchiveWriter h5((folder / "database.h5").string());
      h5.write_attribute("format", "compax RVE response database 1");
      h5.write_attribute("units", "stress Pa, density and strain 1");
      std::vector<double> branch, density, shear, stress;
      for (const coupling::DatabaseRow &r : db.rows)
        {
          branch.push_back(r.branch);
          density.push_back(r.relative_density);
          shear.push_back(r.shear_strain);
          for (int k = 0; k < 6; ++k)
            stress.push_back(r.stress[k]);
        }
      h5.write_array("rows/branch", branch);
      h5.write_array("rows/relative_density", density);
      h5.write_array("rows/shear_strain", shear);
      h5.write_array("rows/stress", stress, {db.rows.size(), 6});
      std::vector<double> b;
      for (const coupling::DatabaseBranch &br : db.branches)
        b.insert(b.end(),
                 {br.relative_density,
                  br.unloaded_density,
                  br.elastic.youngs_modulus,
                  br.elastic.poisson_ratio,
                  br.shear_failure.p,
                  br.shear_failure.q,
                  br.confined_shear_failure.p,
                  br.confined_shear_failure.q});
      h5.write_array("branches", b, {db.branches.size(), 8});
      h5.write_attribute("branches_columns",
                         "relative_density, unloaded_density, E, nu, "
                         "shear_p, shear_q, confined_shear_p, "
                         "confined_shear_q");
      h5.commit();
    }

    void
    write_fit(const std::filesystem::path            &folder,
              const std::vector<coupling::DpcFitRow> &rows)
    {
      CsvWriter csv(folder / "dpc_table.csv", fem::DpcTable::columns());
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

    class DatabaseCommand : public Command
    {
    public:
      std::string
      name() const override
      {
        return "database";
      }

      std::string
      summary() const override
      {
        return "RVE response database and the Drucker-Prager Cap fitted "
               "to it";
      }

      std::string
      description() const override
      {
        return "Runs one periodic RVE of bonded elasto-plastic spheres "
               "along the paths a continuum law needs: uniaxial-strain "
               "(die-like) compaction to the final density; at each branch "
               "density, axial unloading until the cell carries no axial "
               "stress, the elastic moduli of the unloaded cell (condensed "
               "tangent, isotropic projection), and two constant-volume "
               "shear probes (from the unloaded cell, and after a small "
               "volumetric compression) whose plateaus give the shear "
               "failure line. Fits a density-dependent Drucker-Prager Cap: "
               "shear line through the two failures, cap through the "
               "compaction state with the uniaxial flow normal. Writes "
               "database.csv and database.h5 (every equilibrated state), "
               "branches.csv, dpc_table.csv (the format `compax tablet` "
               "reads as its DPC table, so the tablet runs on "
               "particle-derived behaviour) and dpc_table.png. Default: 200 "
               "particles of Material 1 (Gonzalez 2018), branches at 0.70, "
               "0.75, 0.80, 0.85; about 10 s.";
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_rve_cell_parameters(prm);
        prm.enter_subsection("Paths");
        declare_quantity(prm,
                         "Final relative density",
                         "0.85",
                         open(0.0, 1.0),
                         "-",
                         "Uniaxial compaction stops here.");
        declare_quantity(prm,
                         "Compaction strain step",
                         "0.01",
                         open(0.0, 0.1),
                         "-",
                         "Axial logarithmic strain per compaction step.");
        prm.declare_entry("Branch densities",
                          "0.70, 0.75, 0.80, 0.85",
                          dealii::Patterns::List(dealii::Patterns::Double(0, 1),
                                                 2),
                          "Relative densities [-] at which the path "
                          "branches into unloading and shear probes: "
                          "increasing, above the initial and at most the "
                          "final density; one DPC table row each.");
        declare_quantity(prm,
                         "Shear strain",
                         "0.04",
                         open(0.0, 0.5),
                         "-",
                         "Engineering shear strain gamma_xz of each probe.");
        prm.declare_entry("Shear steps",
                          "20",
                          dealii::Patterns::Integer(2, 10000),
                          "Steps of each shear probe, in [2, 1e4]; the "
                          "second half gives the failure state.");
        declare_quantity(prm,
                         "Confinement strain",
                         "0.004",
                         open(0.0, 0.1),
                         "-",
                         "Volumetric compression before the second shear "
                         "probe.");
        prm.leave_subsection();
        declare_rve_solver_parameters(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        read_study(prm);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const DatabaseStudy study = read_study(prm);
        const auto          t0    = std::chrono::steady_clock::now();
        auto                say   = [&](const std::string &line) {
          const double s = std::chrono::duration<double>(
                             std::chrono::steady_clock::now() - t0)
                             .count();
          std::cout << "  [" << std::fixed << std::setprecision(1) << s
                    << " s] " << line << std::defaultfloat << std::endl;
        };
        std::cout << "compax database: " << study.spec.packing.particle_count
                  << " particles (" << study.cell.size_description
                  << "), compaction to " << study.spec.final_density
                  << std::endl;
        coupling::RveDatabase db;
        try
          {
            db
              = coupling::build_rve_database(study.spec, study.cell.model, say);
          }
        catch (const std::runtime_error &e)
          {
            std::cerr << "compax database: " << e.what() << std::endl;
            return not_converged;
          }
        write_rows(folder, db);
        write_archive(folder, db);

        CsvWriter branches(folder / "branches.csv",
                           {"relative_density",
                            "unloaded_density",
                            "youngs_modulus",
                            "poisson_ratio",
                            "shear_p",
                            "shear_q",
                            "confined_shear_p",
                            "confined_shear_q"});
        for (const coupling::DatabaseBranch &b : db.branches)
          {
            branches << b.relative_density << b.unloaded_density
                     << b.elastic.youngs_modulus << b.elastic.poisson_ratio
                     << b.shear_failure.p << b.shear_failure.q
                     << b.confined_shear_failure.p
                     << b.confined_shear_failure.q;
            branches.end_row();
          }
        branches.close();

        std::vector<std::string> notes;
        const auto rows = coupling::fit_drucker_prager_cap(db, &notes);
        write_fit(folder, rows);
        for (const std::string &n : notes)
          std::cout << "  note: " << n << std::endl;
        std::cout << "  dpc_table.csv is a DPC table for `compax tablet`"
                  << std::endl;
        return success;
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_database_command()
  {
    return std::make_unique<DatabaseCommand>();
  }
} // namespace compax::cli

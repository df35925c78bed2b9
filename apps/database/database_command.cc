#include "apps/database/database_command.h"

#include "apps/cli/archive_entry.h"
#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/common/gnuplot.h"
#include "apps/database/database_study.h"
#include "apps/rve/rve_parameters.h"
#include "coupling/database_validation.h"
#include "coupling/hdf5_archive.h"
#include "coupling/rve_archive.h"
#include "coupling/rve_database.h"
#include "fem/dpc_table.h"
#include "fem/drucker_prager_cap.h"

#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    /// Options of the command only (not of the database a tablet builds).
    struct DatabaseRunOptions
    {
      int         stop_after_branches = 0;
      std::string resume_from;
      bool        held_out_packing = true;
    };

    void
    declare_run_options(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoints");
      prm.declare_entry("Stop after branches",
                        "0",
                        dealii::Patterns::Integer(0, 1000),
                        "Stop after this many completed branches (with "
                        "checkpoints/database.h5) and publish the rows so "
                        "far; 0: run to the end. After every branch the "
                        "run writes checkpoints/database.h5 (rows, branches "
                        "and the compaction cell) and refreshes its contact "
                        "list and solver state, so a resumed run repeats "
                        "the uninterrupted one exactly.");
      prm.declare_entry("Resume from",
                        "",
                        dealii::Patterns::Anything(),
                        "A checkpoints/database.h5 (relative to the .prm) "
                        "of an earlier run with the same parameters (all "
                        "but Checkpoints and Validation; the first that "
                        "differs is named): continue after its last "
                        "completed branch. A damaged or foreign file is "
                        "refused. Empty: start afresh.");
      prm.leave_subsection();
      prm.enter_subsection("Validation");
      prm.declare_entry("Held-out packing",
                        "true",
                        dealii::Patterns::Bool(),
                        "Also run every path on a second packing (Packing/"
                        "Seed + 1), not used in the fit: validation.csv "
                        "then holds the fitted law's error on that packing "
                        "and the packing-to-packing scatter of the RVE "
                        "itself (the yardstick of the law's error). "
                        "Doubles the run time.");
      prm.leave_subsection();
    }

    DatabaseRunOptions
    get_run_options(dealii::ParameterHandler &prm)
    {
      DatabaseRunOptions o;
      prm.enter_subsection("Checkpoints");
      o.stop_after_branches = prm.get_integer("Stop after branches");
      o.resume_from         = prm.get("Resume from");
      prm.leave_subsection();
      prm.enter_subsection("Validation");
      o.held_out_packing = prm.get_bool("Held-out packing");
      prm.leave_subsection();
      if (!o.resume_from.empty())
        o.resume_from = resolve_input_path(o.resume_from).string();
      return o;
    }

    /// The parameters that shape the database (all but Checkpoints and
    /// Validation), as canonical text: a checkpoint resumes only the same
    /// study.
    std::string
    study_fingerprint(const dealii::ParameterHandler &prm)
    {
      return canonical_parameters(prm, {}, {"Checkpoints", "Validation"});
    }

    void
    write_checkpoint(const std::filesystem::path &file,
                     const std::string           &fingerprint,
                     const coupling::RveDatabase &db,
                     const dem::PeriodicBed      &bed)
    {
      std::filesystem::create_directories(file.parent_path());
      coupling::Hdf5ArchiveWriter h5(
        file.string(),
        {coupling::archive_kind::database_checkpoint, fingerprint});
      write_database(h5, db);
      coupling::save_rve(h5, "rve", bed);
      h5.commit();
    }

    coupling::DatabaseResume
    read_checkpoint(const std::string       &file,
                    const std::string       &fingerprint,
                    const dem::ContactModel &model)
    {
      const std::string        entry = "Checkpoints/Resume from";
      coupling::DatabaseResume r;
      read_archive_entry(
        entry, file, coupling::archive_kind::database_checkpoint, [&] {
          const coupling::Hdf5ArchiveReader h5(
            file, coupling::archive_kind::database_checkpoint, fingerprint);
          r.database = read_database(h5);
          r.bed      = coupling::load_rve(h5, "rve", model);
        });
      if (r.database.rows.empty() || r.database.branches.empty())
        reject_entry(entry,
                     file,
                     "a database checkpoint without a completed branch");
      return r;
    }

    /// Reads Checkpoints/Resume from and checks it against Stop after
    /// branches (the run and --check alike).
    std::optional<coupling::DatabaseResume>
    prepare_resume(const DatabaseRunOptions &options,
                   const std::string        &fingerprint,
                   const dem::ContactModel  &model)
    {
      if (options.resume_from.empty())
        return std::nullopt;
      coupling::DatabaseResume resume
        = read_checkpoint(options.resume_from, fingerprint, model);
      const int done = static_cast<int>(resume.database.branches.size());
      if (options.stop_after_branches > 0
          && options.stop_after_branches <= done)
        reject_entry("Checkpoints/Stop after branches",
                     std::to_string(options.stop_after_branches),
                     "the checkpoint has " + std::to_string(done)
                       + " branches done already; stop later or set 0");
      return resume;
    }

    /// branches.csv; the plastic density and fitted cap of each branch
    /// when the fit is given (empty cells otherwise).
    void
    write_branches(const std::filesystem::path            &folder,
                   const coupling::RveDatabase            &db,
                   const std::vector<coupling::DpcFitRow> &fit = {})
    {
      CsvWriter branches(folder / "branches.csv",
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

    /// validation.csv: per path, the fitted law against the RVE it was
    /// fitted to, against the held-out packing, and the RVE's own
    /// packing-to-packing scatter.
    void
    write_validation(
      const std::filesystem::path &folder,
      const std::vector<
        std::pair<std::string, std::vector<coupling::PathError>>> &tables)
    {
      CsvWriter csv(folder / "validation.csv",
                    {"comparison",
                     "branch",
                     "path",
                     "role",
                     "relative_density",
                     "points",
                     "stress_error",
                     "p_error",
                     "q_error"});
      for (const auto &[comparison, errors] : tables)
        for (const coupling::PathError &e : errors)
          {
            csv << comparison << e.branch << e.path
                << std::string(e.training ? "training" : "held_out")
                << e.relative_density << static_cast<int>(e.points)
                << e.stress_error << e.p_error << e.q_error;
            csv.end_row();
          }
      csv.close();
    }

    /// validation_rows.csv: the RVE's and the law's stress at every row.
    void
    write_validation_rows(const std::filesystem::path &folder,
                          const coupling::RveDatabase &rve,
                          const coupling::RveDatabase &law)
    {
      CsvWriter csv(folder / "validation_rows.csv",
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

    /// validation.png: p and q of the RVE and of the fitted law at every
    /// row of validation_rows.csv.
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

    std::string
    percent(const double x)
    {
      std::ostringstream o;
      o << std::fixed << std::setprecision(1) << 100.0 * x << " %";
      return o.str();
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
               "tangent, isotropic projection), two constant-volume "
               "shear probes (from the unloaded cell, and after a small "
               "volumetric compression) whose plateaus give the shear "
               "failure line, and radial-strain probes from the loaded "
               "state (eps_rr / eps_zz between isochoric and hydrostatic). "
               "Fits a density-dependent Drucker-Prager Cap: "
               "shear line through the two failures, cap through the "
               "compaction state with the uniaxial flow normal. Then drives "
               "the fitted law along every path (training paths, the "
               "held-out radial probes, and all paths of a second, held-out "
               "packing) and writes its relative stress error per path to "
               "validation.csv, with the RVE's own packing-to-packing "
               "scatter. Writes database.csv and database.h5 (every "
               "equilibrated state with strain, stress, p, q), "
               "branches.csv, dpc_table.csv (the format `compax tablet` "
               "reads as its DPC table) and dpc_table.png; prints progress "
               "per path; checkpoints/database.h5 after every branch "
               "(Checkpoints/Resume from continues an interrupted run). "
               "Default: 200 particles of Material 1 (Gonzalez 2018), "
               "branches at 0.70, 0.75, 0.80, 0.85.";
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_database_parameters(prm);
        declare_run_options(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        const DatabaseStudy      study   = get_database_study(prm);
        const DatabaseRunOptions options = get_run_options(prm);
        prepare_resume(options, study_fingerprint(prm), study.cell.model);
        // The held-out packing is drawn with the next seed.
        check_deposit_density(study.spec.packing,
                              options.held_out_packing ? 2 : 1);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const DatabaseStudy      study       = get_database_study(prm);
        const DatabaseRunOptions options     = get_run_options(prm);
        const std::string        fingerprint = study_fingerprint(prm);
        const auto               t0          = std::chrono::steady_clock::now();
        auto                     elapsed     = [&]() {
          return std::chrono::duration<double>(std::chrono::steady_clock::now()
                                               - t0)
            .count();
        };
        auto say = [&](const std::string &line) {
          std::cout << "  [" << std::fixed << std::setprecision(1) << elapsed()
                    << " s] " << line << std::defaultfloat << std::endl;
        };
        std::optional<coupling::DatabaseResume> resume
          = prepare_resume(options, fingerprint, study.cell.model);
        std::cout << "compax database: " << study.spec.packing.particle_count
                  << " particles (" << study.cell.size_description
                  << "), compaction to " << study.spec.final_density
                  << std::endl;
        coupling::DatabaseControl control;
        control.resume              = resume ? &*resume : nullptr;
        control.stop_after_branches = options.stop_after_branches;
        const auto checkpoint       = folder / "checkpoints" / "database.h5";
        control.branch_done
          = [&](const coupling::RveDatabase &db, const dem::PeriodicBed &bed) {
              write_checkpoint(checkpoint, fingerprint, db, bed);
            };
        coupling::RveDatabase db;
        try
          {
            db = coupling::build_rve_database(study.spec,
                                              study.cell.model,
                                              say,
                                              control);
          }
        catch (const std::runtime_error &e)
          {
            std::cerr << "compax database: " << e.what() << std::endl;
            return not_converged;
          }
        write_database_rows(folder, db);
        write_database_archive(folder, db, fingerprint);
        if (db.stopped)
          {
            write_branches(folder, db);
            std::cout << "Stopped as asked after " << db.branches.size()
                      << " branches; continue with\n  set Resume from = "
                         "<OUTDIR>/checkpoints/database.h5\nin subsection "
                         "Checkpoints."
                      << std::endl;
            return success;
          }
        const double t_database = elapsed();

        std::vector<std::string> notes;
        const auto rows = coupling::fit_drucker_prager_cap(db, &notes);
        write_dpc_table(folder, rows);
        write_branches(folder, db, rows);
        for (const std::string &n : notes)
          std::cout << "  note: " << n << std::endl;

        // Measured error of the fitted law.
        const fem::DruckerPragerCap law(to_dpc_table(rows));
        std::vector<std::pair<std::string, std::vector<coupling::PathError>>>
          tables;
        try
          {
            const coupling::RveDatabase dpc = coupling::with_stresses(
              db, coupling::drive_along_database(db, law));
            tables.emplace_back("dpc_vs_rve", coupling::path_errors(db, dpc));
            write_validation_rows(folder, db, dpc);
            plot_validation(folder);
            std::cout << "Fitted DPC against the RVE (relative RMS stress "
                         "error): training paths "
                      << percent(coupling::pooled_stress_error(db, dpc, true))
                      << ", held-out radial probes "
                      << percent(coupling::pooled_stress_error(db, dpc, false))
                      << std::endl;
            if (options.held_out_packing)
              {
                say("held-out packing (seed "
                    + std::to_string(study.spec.packing.seed + 1) + ")");
                coupling::DatabaseSpec other = study.spec;
                ++other.packing.seed;
                const coupling::RveDatabase held
                  = coupling::build_rve_database(other, study.cell.model, {});
                const coupling::RveDatabase held_dpc = coupling::with_stresses(
                  held, coupling::drive_along_database(held, law));
                auto e_dpc = coupling::path_errors(held, held_dpc);
                auto e_rve = coupling::path_errors(db, held);
                tables.emplace_back("dpc_vs_held_out_packing", e_dpc);
                tables.emplace_back("rve_packing_scatter", e_rve);
                std::cout
                  << "Fitted DPC against the held-out packing: training "
                     "paths "
                  << percent(
                       coupling::pooled_stress_error(held, held_dpc, true))
                  << ", radial probes "
                  << percent(
                       coupling::pooled_stress_error(held, held_dpc, false))
                  << "; RVE packing-to-packing scatter: training paths "
                  << percent(coupling::pooled_stress_error(db, held, true))
                  << ", radial probes "
                  << percent(coupling::pooled_stress_error(db, held, false))
                  << std::endl;
              }
          }
        catch (const std::runtime_error &e)
          {
            std::cerr << "compax database: validation: " << e.what()
                      << std::endl;
            return not_converged;
          }
        write_validation(folder, tables);
        std::cout << "  database " << std::fixed << std::setprecision(1)
                  << t_database << " s, validation " << elapsed() - t_database
                  << " s" << std::defaultfloat << std::endl;
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

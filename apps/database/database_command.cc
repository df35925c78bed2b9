#include "apps/database/database_command.h"

#include "apps/cli/archive_entry.h"
#include "apps/cli/input_error.h"
#include "apps/database/database_outputs.h"
#include "coupling/parameters/database_parameters.h"
#include "coupling/parameters/rve_parameters.h"
#include "coupling/rve_database_archive.h"
#include "coupling/rve_database_study.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    /// Reads Checkpoints/Resume from (a damaged or foreign file is bad
    /// input naming the entry) and checks it against Stop after branches
    /// (the run and --check alike).
    std::optional<coupling::DatabaseResume>
    prepare_resume(const coupling::DatabaseRunOptions &options,
                   const std::string                  &fingerprint,
                   const dem::ContactModel            &model)
    {
      if (options.resume_from.empty())
        return std::nullopt;
      const std::string        entry = "Checkpoints/Resume from";
      coupling::DatabaseResume resume
        = read_archive_entry(entry,
                             options.resume_from,
                             coupling::archive_kind::database_checkpoint,
                             [&] {
                               return coupling::read_database_checkpoint(
                                 options.resume_from, fingerprint, model);
                             });
      if (resume.database.rows.empty() || resume.database.branches.empty())
        reject_entry(entry,
                     options.resume_from,
                     "a database checkpoint without a completed branch");
      const int done = static_cast<int>(resume.database.branches.size());
      if (options.stop_after_branches > 0
          && options.stop_after_branches <= done)
        reject_entry("Checkpoints/Stop after branches",
                     std::to_string(options.stop_after_branches),
                     "the checkpoint has " + std::to_string(done)
                       + " branches done already; stop later or set 0");
      return resume;
    }

    std::string
    percent(const double x)
    {
      std::ostringstream o;
      o << std::fixed << std::setprecision(1) << 100.0 * x << " %";
      return o.str();
    }

    /// The pooled errors of the fitted law (and of the held-out packing's
    /// scatter) on the training paths and the held-out radial probes.
    void
    print_validation(const std::vector<coupling::DatabaseComparison> &c)
    {
      if (!c.empty())
        std::cout << "Fitted DPC against the RVE (relative RMS stress "
                     "error): training paths "
                  << percent(c[0].training_error) << ", held-out radial probes "
                  << percent(c[0].held_out_error) << std::endl;
      if (c.size() == 3)
        std::cout << "Fitted DPC against the held-out packing: training "
                     "paths "
                  << percent(c[1].training_error) << ", radial probes "
                  << percent(c[1].held_out_error)
                  << "; RVE packing-to-packing scatter: training paths "
                  << percent(c[2].training_error) << ", radial probes "
                  << percent(c[2].held_out_error) << std::endl;
    }

    class DatabaseCommand : public Command
    {
    public:
      DatabaseCommand()
          : Command(
            {"database",
             "RVE response database and the Drucker-Prager Cap fitted "
             "to it",
             "Runs one periodic RVE of bonded elasto-plastic spheres "
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
             "branches at 0.70, 0.75, 0.80, 0.85."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        coupling::declare_database_parameters(prm);
        coupling::declare_database_run_options(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        const coupling::DatabaseSetup setup = coupling::get_database_setup(prm);
        const coupling::DatabaseRunOptions options
          = coupling::get_database_run_options(prm);
        prepare_resume(options,
                       coupling::database_fingerprint(prm),
                       setup.cell.model);
        // The held-out packing is drawn with the next seed.
        coupling::check_deposit_density(setup.spec.packing,
                                        options.held_out_packing ? 2 : 1);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const coupling::DatabaseSetup setup = coupling::get_database_setup(prm);
        const coupling::DatabaseRunOptions options
          = coupling::get_database_run_options(prm);
        const std::string fingerprint = coupling::database_fingerprint(prm);
        const std::optional<coupling::DatabaseResume> resume
          = prepare_resume(options, fingerprint, setup.cell.model);
        std::cout << "compax database: " << setup.spec.packing.particle_count
                  << " particles (" << setup.cell.size_description
                  << "), compaction to " << setup.spec.final_density
                  << std::endl;

        coupling::RveDatabaseStudyOptions study_options;
        study_options.spec                = setup.spec;
        study_options.held_out_packing    = options.held_out_packing;
        study_options.stop_after_branches = options.stop_after_branches;
        coupling::RveDatabaseStudy study(setup.cell.model, study_options);
        const auto                 t0 = std::chrono::steady_clock::now();
        study.on_progress             = [t0](const std::string &line) {
          const std::chrono::duration<double> elapsed
            = std::chrono::steady_clock::now() - t0;
          std::cout << "  [" << std::fixed << std::setprecision(1)
                    << elapsed.count() << " s] " << line << std::defaultfloat
                    << std::endl;
        };
        const auto checkpoint = folder / "checkpoints" / "database.h5";
        study.on_branch_done  = [&](const coupling::RveDatabase &db,
                                   const dem::PeriodicBed      &bed) {
          coupling::write_database_checkpoint(checkpoint, fingerprint, db, bed);
        };
        const coupling::RveDatabaseStudyResult result
          = study.run(resume ? &*resume : nullptr);
        if (result.outcome == coupling::RveDatabaseOutcome::database_failed)
          {
            std::cerr << "compax database: " << result.failure << std::endl;
            return not_converged;
          }

        const coupling::RveDatabase &db = result.database;
        write_database_rows(folder, db);
        coupling::write_database_archive(folder / "database.h5",
                                         db,
                                         fingerprint);
        if (result.outcome == coupling::RveDatabaseOutcome::stopped)
          {
            write_branches(folder, db);
            std::cout << "Stopped as asked after " << db.branches.size()
                      << " branches; continue with\n  set Resume from = "
                         "<OUTDIR>/checkpoints/database.h5\nin subsection "
                         "Checkpoints."
                      << std::endl;
            return success;
          }
        write_dpc_table(folder, result.fit);
        write_branches(folder, db, result.fit);
        for (const std::string &n : result.notes)
          std::cout << "  note: " << n << std::endl;
        if (result.validation.law)
          {
            write_validation_rows(folder, db, *result.validation.law);
            plot_validation(folder);
          }
        print_validation(result.validation.comparisons);
        if (result.outcome == coupling::RveDatabaseOutcome::validation_failed)
          {
            std::cerr << "compax database: validation: " << result.failure
                      << std::endl;
            return not_converged;
          }
        write_validation(folder, result.validation.comparisons);
        std::cout << "  database " << std::fixed << std::setprecision(1)
                  << result.database_seconds << " s, validation "
                  << result.validation_seconds << " s" << std::defaultfloat
                  << std::endl;
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

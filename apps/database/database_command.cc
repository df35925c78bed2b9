#include "apps/database/database_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/common/gnuplot.h"
#include "apps/database/database_study.h"
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
        declare_database_parameters(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        get_database_study(prm);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const DatabaseStudy study = get_database_study(prm);
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
        write_database_rows(folder, db);
        write_database_archive(folder, db);

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
        write_dpc_table(folder, rows);
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

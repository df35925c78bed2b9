#include "apps/tablet/tablet_command.h"

#include "apps/tablet/multiscale_material_setup.h"
#include "coupling/parameters/multiscale_parameters.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/tablet/tablet_report.h"
#include "coupling/tablet_checkpoint.h"
#include "coupling/tablet_parameters.h"
#include "coupling/tablet_study.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace compax::cli
{
  namespace
  {
    using coupling::TabletSetup;

    void
    declare(dealii::ParameterHandler &prm)
    {
      coupling::declare_tablet_parameters(prm, coupling::tablet_materials());
      coupling::declare_multiscale_parameters(prm);
    }

    TabletSetup
    read(dealii::ParameterHandler &prm)
    {
      TabletSetup s
        = coupling::parse_tablet_parameters(prm, coupling::tablet_materials());
      if (!s.deferred_material.empty())
        coupling::check_multiscale_parameters(prm);
      return s;
    }

    template <int dim>
    coupling::TabletStudyResult
    run_model(const TabletSetup           &setup,
              const std::filesystem::path &folder,
              MPI_Comm                     comm)
    {
      const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      coupling::TabletStudyOptions options = setup.output;
      options.folder                       = folder;
      coupling::TabletStudy<dim> study(
        setup.solver, setup.process, setup.material, options, comm);
      if (root)
        print_tablet_header(study,
                            *setup.material,
                            dealii::Utilities::MPI::n_mpi_processes(comm));
      study.on_resume = [&](const fem::TabletStep &last) {
        if (root)
          std::cout << "Resuming after step " << last.index << " from "
                    << setup.output.resume_from.string() << '\n';
      };
      study.on_step = [&](const coupling::TabletProgress &p) {
        if (root)
          print_tablet_step(p);
      };
      const coupling::TabletStudyResult result = [&] {
        try
          {
            return study.run();
          }
        catch (const coupling::TabletResumeError &e)
          {
            reject_entry("Output/Resume from",
                         setup.output.resume_from.string(),
                         e.what());
          }
      }();
      if (root)
        {
          print_tablet_summary(result, setup.process);
          plot_tablet(folder);
        }
      return result;
    }

    class TabletCommand : public Command
    {
    public:
      TabletCommand()
          : Command(
            {"tablet",
             "continuum die compaction, unloading and ejection (deal.II)",
             "Quasi-static finite element model of a powder compact in a "
             "rigid cylindrical die with flat-faced or concave (spherical "
             "cup, built-in or Gmsh mesh) upper punch: the upper "
             "punch compacts the powder (lower punch fixed), is withdrawn "
             "(the compact separates freely), and the lower punch ejects "
             "the tablet, which expands freely above the die. "
             "Axisymmetric r-z model (or a 3-D quarter cylinder), updated "
             "Lagrangian large deformation, Newton with consistent "
             "tangent, penalty contact with Coulomb wall friction, "
             "Trilinos linear algebra on a distributed mesh (runs under "
             "mpirun). Materials: density-dependent Drucker-Prager Cap "
             "(tables in CSV) or linear elasticity.\n\nWrites tablet.csv "
             "(step,time,stage,punch displacements, upper/lower punch and "
             "mean die-wall pressures, ejection force, mean relative "
             "density, forces, ..., newton_iterations, mean_stress: "
             "tr(sigma) / 3 averaged over the compact's current volume, "
             "tension positive, which equilibrium makes the boundary "
             "tractions' virial over the volume, ~0 for the free ejected "
             "tablet; SI units, pressures positive in compression; the "
             "summary adds the FE2 floor's share of it), tablet.pvd with "
             "tablet_NNNN.pvtu/vtu fields "
             "(displacement, relative density, stress, plastic strain) "
             "and the same fields as tablet_NNNN.h5 with tablet.xdmf, "
             "tablet.png (pressures and ejection force against time) with "
             "its gnuplot script, and prints progress and a summary.\n\n"
             "Built-in default: a 10 mm flat-faced tablet of "
             "microcrystalline cellulose (built-in DPC table), 7 mm fill "
             "at relative density 0.5, compacted to 0.9 in the die, "
             "unloaded and ejected, mu = 0.25."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        read(prm);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        return run_tablet(prm, folder).code;
      }
    };
  } // namespace

  TabletRun
  run_tablet(dealii::ParameterHandler &prm, const std::filesystem::path &folder)
  {
    TabletSetup setup = read(prm);
    TabletRun   run;
    // All ranks write their field pieces into rank 0's folder.
    std::string shared = folder.string();
    shared = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, shared, 0);
    if (!setup.deferred_material.empty())
      {
        try
          {
            // The axial row of the model's stress frame: (r, z, theta)
            // in r-z, (x, y, z) in 3-D; Gauss points per cell.
            const unsigned int dim = setup.three_d ? 3 : 2;
            setup.material         = make_multiscale_material(
              prm,
              setup.deferred_material,
              shared,
              dim - 1,
              dealii::Utilities::pow(setup.solver.degree + 1, dim),
              MPI_COMM_WORLD,
              &run.database);
          }
        catch (const std::runtime_error &e)
          {
            // Every rank fails alike; one reports.
            if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
              std::cerr << "compax tablet: " << e.what() << std::endl;
            run.code = not_converged;
            return run;
          }
      }
    run.result = setup.three_d ? run_model<3>(setup, shared, MPI_COMM_WORLD)
                               : run_model<2>(setup, shared, MPI_COMM_WORLD);
    run.code   = run.result->converged ? success : not_converged;
    return run;
  }

  std::unique_ptr<Command>
  make_tablet_command()
  {
    return std::make_unique<TabletCommand>();
  }
} // namespace compax::cli

#include "apps/die/die_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/common/gnuplot.h"
#include "apps/die/bed_checkpoint.h"
#include "apps/die/branch_states.h"
#include "apps/die/die_parameters.h"
#include "apps/die/die_study_fits.h"
#include "dem/die/die_setup.h"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>

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
      CsvWriter csv(file,
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
              << b.bonding_surface_ejected << b.tablet.youngs_modulus
              << b.tablet.poisson_ratio;
          csv.end_row();
        }
    }

    /// Punch and die-wall pressure, and Z, against in-die density, with the
    /// fits of Eqs. (14) and (15) where the study determined them.
    void
    plot(const std::filesystem::path &folder, const CompactionFits &fits)
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

    /// The bed saved in checkpoints/branch-<k>.h5, and k.
    dem::Bed
    load_branch_checkpoint(const std::string       &file,
                           const dem::ContactModel &model,
                           int                     &branch)
    {
      const std::string name = std::filesystem::path(file).stem().string();
      const auto        dash = name.rfind('-');
      branch
        = dash == std::string::npos ? 1 : std::atoi(name.c_str() + dash + 1);
      if (branch < 1)
        branch = 1;
      try
        {
          const coupling::Hdf5ArchiveReader archive(file);
          return load_bed(archive, "bed", model);
        }
      catch (const std::exception &e)
        {
          reject_entry("Protocol/Rerun branch from",
                       file,
                       std::string("not a compax die checkpoint (") + e.what()
                         + ")");
        }
    }

    class DieCommand : public Command
    {
    public:
      std::string
      name() const override
      {
        return "die";
      }

      std::string
      summary() const override
      {
        return "die compaction, unloading and ejection of a particle bed";
      }

      std::string
      description() const override
      {
        return "Fills a rigid cylindrical die with bonded elasto-plastic "
               "spheres by ballistic deposition, compacts the bed by the "
               "upper punch through a sequence of static equilibria "
               "(trust-region Newton; internal variables updated on "
               "converged steps only, Gonzalez 2018 Eq. 13), unloads it "
               "from each unloading point until the punch carries no force, "
               "and ejects it (Gonzalez 2018, Sec. 5).\n\nWrites die.csv "
               "(one row per converged step: stage, branch, densities, "
               "punch and die-wall forces and pressures, coordination "
               "number, bonding surface, bonds formed and broken, elastic "
               "recovery, residual radial and ejection pressure, solver "
               "iterations and residual), branches.csv (one row per "
               "unloading branch, with the tablet's E and nu), fits.csv and "
               "fits.md (Eqs. 14-24 fitted to the study), die.png.\n\n"
               "Built-in default: Material 1 of Gonzalez 2018 Table 1 "
               "(R = 220 um), 400 particles in a 4 mm die, compacted to an "
               "in-die relative density of 0.87, with unloading branches (and "
               "ejection) from 0.75, 0.79, 0.83 and 0.87. The "
               "full study of Sec. 5 is in apps/parameters/"
               "die_material1_6512.prm and die_material2_6512.prm.";
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_die_parameters(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        get_die_study(prm);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        DieStudy   study        = get_die_study(prm);
        const auto started      = std::chrono::steady_clock::now();
        int        rerun_branch = 0;
        dem::Bed   bed;
        if (!study.rerun_branch_from.empty())
          {
            bed = load_branch_checkpoint(study.rerun_branch_from,
                                         study.model,
                                         rerun_branch);
            std::cout << "Rerunning unloading branch " << rerun_branch
                      << " from " << study.rerun_branch_from
                      << " (in-die relative density " << bed.relative_density()
                      << ")" << std::endl;
          }
        else
          {
            std::cout << "Packing " << study.deposition.n_particles
                      << " particles by ballistic deposition in a "
                      << study.deposition.die_diameter * 1e3 << " mm die ..."
                      << std::endl;
            bed                = dem::fill_die(study.deposition);
            const double rho_0 = bed.relative_density();
            std::cout << "  initial in-die relative density " << rho_0
                      << std::endl;
            if (study.final_density <= rho_0)
              reject_entry("Protocol/Final relative density",
                           format_number(study.final_density),
                           "must exceed the packing's relative density "
                             + format_number(rho_0));
            study.protocol.compaction_targets
              = dem::density_targets(rho_0,
                                     study.final_density,
                                     study.compaction_steps);
          }

        std::ofstream      csv(folder / "die.csv");
        dem::DieCompaction die(std::move(bed),
                               study.model,
                               study.protocol,
                               study.equilibrium);
        die.set_output(&csv, &std::cout);
        BranchStateWriter branch_states(folder);
        die.on_branch_state = [&branch_states](const dem::Bed    &state,
                                               const std::string &stage,
                                               int                branch) {
          branch_states(state, stage, branch);
        };
        int code = success;
        try
          {
            if (rerun_branch > 0)
              die.rerun_branch(rerun_branch);
            else
              die.run();
          }
        catch (const std::runtime_error &e)
          {
            std::cerr << "compax die: " << e.what()
                      << "; the converged steps are kept in die.csv and the "
                         "last converged state in last_converged.h5\n";
            coupling::Hdf5ArchiveWriter archive(
              (folder / "last_converged.h5").string());
            archive.write_attribute("format", "compax die bed state 1");
            archive.write_attribute("failure", die.failure());
            save_bed(archive, "bed", die.last_converged());
            archive.commit();
            code = not_converged;
          }
        csv.close();

        write_branches(folder / "branches.csv", die.branches());
        plot(folder, write_die_fits(folder, die.records(), die.branches()));

        const double seconds = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - started)
                                 .count();
        std::cout << "Solver: " << die.newton_iterations
                  << " Newton iterations (" << die.cg_iterations << " CG), "
                  << die.assemblies << " assemblies (" << die.assembly_seconds
                  << " s), linear solves " << die.linear_seconds
                  << " s, relaxation " << die.fire_seconds << " s; total "
                  << seconds << " s\n";
        return code;
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_die_command()
  {
    return std::make_unique<DieCommand>();
  }
} // namespace compax::cli

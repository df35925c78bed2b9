#include "apps/die/die_command.h"

#include "apps/cli/archive_entry.h"
#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/common/gnuplot.h"
#include "apps/die/bed_checkpoint.h"
#include "apps/die/branch_states.h"
#include "apps/die/die_checkpoint.h"
#include "apps/die/die_parameters.h"
#include "apps/die/die_study_fits.h"
#include "dem/die/die_setup.h"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
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
              << b.bonding_surface_ejected;
          // Too few points on the unloading curve: not determined.
          if (b.tablet.n_points >= 2)
            csv << b.tablet.youngs_modulus << b.tablet.poisson_ratio;
          else
            csv.empty().empty();
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
                  const CompactionFits        &fits)
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

    /// The bed saved in checkpoints/branch-<k>.h5, and k.
    dem::Bed
    load_branch_checkpoint(const DieStudy &study, int &branch)
    {
      return read_archive_entry("Protocol/Rerun branch from",
                                study.rerun_branch_from,
                                coupling::archive_kind::die_branch,
                                [&] {
                                  const coupling::Hdf5ArchiveReader archive(
                                    study.rerun_branch_from,
                                    coupling::archive_kind::die_branch,
                                    study.state_parameters);
                                  const double k
                                    = archive.read_attribute("branch");
                                  if (!(k >= 1 && k <= 1e6))
                                    throw std::runtime_error(
                                      "no branch number");
                                  branch = static_cast<int>(k);
                                  return load_bed(archive, "bed", study.model);
                                });
    }

    /// A run resumed from a compaction checkpoint: where it stands and the
    /// folder of the run that wrote it.
    struct ResumePoint
    {
      dem::Bed              bed;
      dem::DieProgress      progress;
      BranchFiles           branch_files;
      std::filesystem::path old_folder;
    };

    /**
     * Reads and checks Protocol/Resume from (the archive, the parameters,
     * the compaction targets done, the earlier branches' files next to it)
     * and sets the study's compaction targets; throws InputError naming
     * the entry. What the run and --check do alike.
     */
    ResumePoint
    prepare_resume(DieStudy &study)
    {
      const std::string entry = "Protocol/Resume from";
      const std::string file  = study.resume_from;
      ResumePoint       r;
      r.progress = read_archive_entry(
        entry, file, coupling::archive_kind::die_compaction, [&] {
          return read_die_checkpoint(
            file, study.resume_parameters, study.model, r.bed, r.branch_files);
        });
      const int stop = study.protocol.stop_after;
      if (stop > 0 && std::size_t(stop) <= r.progress.completed_targets)
        reject_entry("Protocol/Stop after compaction steps",
                     std::to_string(stop),
                     "counts from the start of the study and must exceed the "
                       + std::to_string(r.progress.completed_targets)
                       + " steps the checkpoint has done (or be 0)");
      set_compaction_targets(study, r.progress.rows.front().relative_density);
      const std::string mismatch
        = dem::DieCompaction(r.bed, study.model, study.protocol)
            .resume_mismatch(r.progress);
      if (!mismatch.empty())
        reject_entry(entry, file, mismatch);
      r.old_folder
        = std::filesystem::absolute(file).parent_path().parent_path();
      try
        {
          BranchStateWriter::verify(r.old_folder, r.branch_files);
        }
      catch (const std::exception &e)
        {
          reject_entry(entry, file, e.what());
        }
      return r;
    }

    /**
     * die.csv as it is written, line by line. A test hook (fault
     * injection) for the kill-and-resume tests: with the environment
     * variable COMPAX_TEST_KILL_AFTER_ROW=<stage>,<branch>,<step> the
     * process kills itself (SIGKILL, no clean-up at all) right after that
     * row reached the file, as a kill from outside at that point would.
     */
    class KillSwitch : public std::streambuf
    {
    public:
      explicit KillSwitch(std::streambuf *file)
          : file(file)
      {
        if (const char *row = std::getenv("COMPAX_TEST_KILL_AFTER_ROW"))
          prefix = std::string(row) + ",";
      }

      ~KillSwitch() override
      {
        file->sputn(line.data(), static_cast<std::streamsize>(line.size()));
      }

    protected:
      int
      overflow(const int c) override
      {
        if (c == traits_type::eof())
          return 0;
        const char ch = static_cast<char>(c);
        xsputn(&ch, 1);
        return c;
      }

      std::streamsize
      xsputn(const char *s, const std::streamsize n) override
      {
        for (std::streamsize i = 0; i < n; ++i)
          {
            line += s[i];
            if (s[i] != '\n')
              continue;
            file->sputn(line.data(), static_cast<std::streamsize>(line.size()));
            if (!prefix.empty() && line.rfind(prefix, 0) == 0)
              {
                file->pubsync();
                ::kill(::getpid(), SIGKILL);
              }
            line.clear();
          }
        return n;
      }

      int
      sync() override
      {
        return file->pubsync();
      }

    private:
      std::streambuf *file;
      std::string     prefix;
      std::string     line;
    };

    /// timing.csv: the wall time of every die.csv row since the run
    /// started (empty for rows taken over from a checkpoint).
    void
    write_timing(const std::filesystem::path       &file,
                 const std::vector<dem::DieRecord> &rows,
                 const std::size_t                  taken_over)
    {
      CsvWriter csv(file, {"stage", "branch", "step", "wall_seconds"});
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

    /// Prints how many particles of each material the bed has.
    void
    report_materials(const dem::Bed &bed, const dem::ContactModel &model)
    {
      if (model.n_materials() < 2)
        return;
      std::vector<std::size_t> count(model.n_materials(), 0);
      for (const unsigned int m : bed.particles.materials)
        if (m < count.size())
          ++count[m];
      std::cout << "  particles per material:";
      for (std::size_t a = 0; a < count.size(); ++a)
        std::cout << (a ? ", " : " ") << count[a] << " of material " << a + 1;
      std::cout << std::endl;
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
               "iterations and residual, and the interior of the compact: "
               "rho_interior, sigma_zz_interior, sigma_rr_interior, the "
               "solid fraction and the axial and radial Love-Weber stress "
               "[Pa, tension positive] of the particles farther than two "
               "mean diameters from the die wall and both punches, nan "
               "when there are none; its wall time per row goes to "
               "timing.csv), branches.csv (one row per "
               "unloading branch, with the tablet's E and nu), fits.csv and "
               "fits.md (Eqs. 14-24 fitted to the study), die.png (punch and "
               "die-wall pressure and Z with the fits of Eqs. 14-15), "
               "branches.png (elastic recovery, residual radial pressure, "
               "bonding surface and tablet E with Eqs. 17, 19, 23, 24), VTU "
               "snapshots, fabric and force histograms, and checkpoints: "
               "checkpoints/branch-<k>.h5 (Protocol/Rerun branch from) and "
               "checkpoints/compaction.h5 every Protocol/Checkpoint interval "
               "steps and at the end (Protocol/Resume from continues an "
               "interrupted run with the same parameters, its output "
               "complete; a foreign or damaged checkpoint is refused; "
               "while running, the output is staged in .<OUTDIR>.partial-<pid> "
               "next to OUTDIR). Two particle species: Material 2 and "
               "Packing/Material fractions. Contact/Contact law = elastic "
               "fills the die with elastic frictionless spheres instead "
               "(no bonding), and Contact/Formulation = nonlocal then "
               "selects the nonlocal contact formulation of Gonzalez & "
               "Cuitino 2012 (Algorithm 1 at every residual) in place of "
               "Hertz.\n\n"
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
        DieStudy study = get_die_study(prm);
        if (!study.resume_from.empty())
          prepare_resume(study);
        else if (!study.rerun_branch_from.empty())
          {
            int branch = 0;
            load_branch_checkpoint(study, branch);
          }
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        DieStudy                   study   = get_die_study(prm);
        const auto                 started = std::chrono::steady_clock::now();
        int                        rerun_branch = 0;
        dem::Bed                   bed;
        std::optional<ResumePoint> resumed;
        if (!study.resume_from.empty())
          {
            resumed = prepare_resume(study);
            bed     = resumed->bed;
            std::cout << "Resuming from " << study.resume_from
                      << " (in-die relative density " << bed.relative_density()
                      << ")" << std::endl;
          }
        else if (!study.rerun_branch_from.empty())
          {
            bed = load_branch_checkpoint(study, rerun_branch);
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
            bed = dem::fill_die(study.deposition);
            std::cout << "  initial in-die relative density "
                      << bed.relative_density() << std::endl;
            set_compaction_targets(study, bed.relative_density());
          }
        report_materials(bed, study.model);
        if (study.protocol.elastic)
          std::cout << "  elastic frictionless spheres, "
                    << (study.protocol.elastic->nonlocal
                          ? "nonlocal contact formulation (Gonzalez & "
                            "Cuitino 2012)"
                          : "Hertz contacts")
                    << std::endl;

        std::ofstream      csv(folder / "die.csv");
        KillSwitch         kill_switch(csv.rdbuf());
        std::ostream       rows(&kill_switch);
        dem::DieCompaction die(std::move(bed),
                               study.model,
                               study.protocol,
                               study.equilibrium);
        die.set_output(&rows, &std::cout);
        BranchStateWriter branch_states(folder, study.state_parameters);
        die.on_branch_state = [&branch_states](const dem::Bed    &state,
                                               const std::string &stage,
                                               int                branch) {
          branch_states(state, stage, branch);
        };
        const auto checkpoint = folder / "checkpoints" / "compaction.h5";
        die.on_checkpoint
          = [&](const dem::Bed &state, const dem::DieProgress &p) {
              write_die_checkpoint(checkpoint.string(),
                                   study.resume_parameters,
                                   state,
                                   p,
                                   branch_states.so_far());
            };
        if (resumed)
          {
            try
              {
                branch_states.carry_over(resumed->old_folder,
                                         resumed->branch_files);
              }
            catch (const std::exception &e)
              {
                reject_entry("Protocol/Resume from",
                             study.resume_from,
                             e.what());
              }
          }
        int code = success;
        try
          {
            if (rerun_branch > 0)
              die.rerun_branch(rerun_branch);
            else if (resumed)
              die.resume(resumed->progress);
            else
              die.run();
            // The final state as a checkpoint too: the output of a resumed
            // run is that of the uninterrupted one.
            if (rerun_branch == 0 && !die.stopped()
                && study.protocol.checkpoint_interval > 0)
              write_die_checkpoint(checkpoint.string(),
                                   study.resume_parameters,
                                   die.bed(),
                                   die.progress_state(),
                                   branch_states.so_far());
            if (die.stopped())
              std::cout << "Stopped as asked; continue with\n  set Resume "
                           "from = <OUTDIR>/checkpoints/compaction.h5\nin "
                           "subsection Protocol."
                        << std::endl;
          }
        catch (const std::runtime_error &e)
          {
            std::cerr << "compax die: " << e.what()
                      << "; the converged steps are kept in die.csv and the "
                         "last converged state in last_converged.h5\n";
            coupling::Hdf5ArchiveWriter archive(
              (folder / "last_converged.h5").string(),
              {coupling::archive_kind::die_state, study.state_parameters});
            archive.write_attribute("failure", die.failure());
            save_bed(archive, "bed", die.last_converged());
            archive.commit();
            code = not_converged;
          }
        rows.flush();
        csv.close();
        write_timing(folder / "timing.csv",
                     die.records(),
                     resumed ? resumed->progress.rows.size() : 0);

        write_branches(folder / "branches.csv", die.branches());
        const CompactionFits fits = write_die_fits(folder,
                                                   die.records(),
                                                   die.branches(),
                                                   die.pressure_resolution());
        plot(folder, fits);
        if (!die.branches().empty())
          plot_branches(folder, fits);

        const double seconds = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - started)
                                 .count();
        std::cout << std::defaultfloat << std::setprecision(4)
                  << "Solver: " << die.newton_iterations
                  << " Newton iterations (" << die.cg_iterations << " CG), "
                  << die.fire_iterations << " FIRE fallback iterations, ";
        // The elastic (Hertz or nonlocal) stepper does not time its
        // assemblies, linear solves and relaxations: print no zeros.
        if (die.assemblies > 0)
          std::cout << die.assemblies << " assemblies (" << die.assembly_seconds
                    << " s), linear solves " << die.linear_seconds
                    << " s, relaxation " << die.fire_seconds << " s, ";
        std::cout << "total " << seconds << " s\n";
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

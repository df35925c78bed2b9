#include "apps/die/die_command.h"

#include "apps/cli/archive_entry.h"
#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/die/branch_states.h"
#include "apps/die/die_outputs.h"
#include "apps/die/kill_switch.h"
#include "coupling/die_checkpoint.h"
#include "coupling/die_state_archive.h"
#include "coupling/parameters/die_parameters.h"
#include "dem/die/die_study.h"
#include "dem/wall_clock.h"

#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace compax::cli
{
  namespace
  {
    /// The bed saved in checkpoints/branch-<k>.h5, and k.
    coupling::DieBranchState
    load_branch_checkpoint(const coupling::DieInput &input)
    {
      return read_archive_entry("Protocol/Rerun branch from",
                                input.rerun_branch_from,
                                coupling::archive_kind::die_branch,
                                [&] {
                                  return coupling::read_die_branch_checkpoint(
                                    input.rerun_branch_from,
                                    input.state_parameters,
                                    input.model);
                                });
    }

    /// The study a .prm asks for, and what a resumed run takes over.
    struct PreparedStudy
    {
      dem::DieStudy study;
      /// Where the run starts, for the log; empty for a fresh deposit.
      std::string origin;
      /// A resumed run: the die.csv rows and branch files taken over, and
      /// the folder of the run that wrote them (empty otherwise).
      std::vector<dem::DieRecord> taken_over;
      coupling::DieBranchFiles    branch_files;
      std::filesystem::path       old_folder;
    };

    /// "<what> <file> (in-die relative density <rho>)".
    std::string
    origin(const std::string &what, const std::string &file, const dem::Bed &b)
    {
      std::ostringstream s;
      s << what << file << " (in-die relative density " << b.relative_density()
        << ")";
      return s.str();
    }

    /**
     * Builds the study: afresh, resumed from Protocol/Resume from (the
     * archive, the parameters, the compaction targets done and the earlier
     * branches' files next to it are checked) or rerunning the branch of
     * Protocol/Rerun branch from; throws InputError naming the entry. What
     * the run and --check do alike.
     */
    PreparedStudy
    prepare_study(const coupling::DieInput &input)
    {
      if (!input.rerun_branch_from.empty() && input.resume_from.empty())
        {
          const auto state = load_branch_checkpoint(input);
          return {dem::DieStudy(input.model,
                                input.study,
                                dem::DieStudyStart::branch(state.bed,
                                                           state.branch)),
                  origin("Rerunning unloading branch "
                           + std::to_string(state.branch) + " from ",
                         input.rerun_branch_from,
                         state.bed),
                  {},
                  {},
                  {}};
        }
      if (input.resume_from.empty())
        return {dem::DieStudy(input.model, input.study), {}, {}, {}, {}};

      const std::string       entry      = "Protocol/Resume from";
      const std::string       file       = input.resume_from;
      coupling::DieCheckpoint checkpoint = read_archive_entry(
        entry, file, coupling::archive_kind::die_compaction, [&] {
          return coupling::read_die_checkpoint(file,
                                               input.resume_parameters,
                                               input.model);
        });
      dem::Bed                 &bed      = checkpoint.bed;
      dem::DieProgress         &progress = checkpoint.progress;
      coupling::DieBranchFiles &files    = checkpoint.branch_files;
      const int                 stop     = input.study.protocol.stop_after;
      if (stop > 0 && std::size_t(stop) <= progress.completed_targets)
        reject_entry("Protocol/Stop after compaction steps",
                     std::to_string(stop),
                     "counts from the start of the study and must exceed the "
                       + std::to_string(progress.completed_targets)
                       + " steps the checkpoint has done (or be 0)");
      const auto old_folder
        = std::filesystem::absolute(file).parent_path().parent_path();
      std::vector<dem::DieRecord> rows = progress.rows;
      dem::DieStudy study = coupling::naming_final_density(input.study, [&] {
        return dem::DieStudy(input.model,
                             input.study,
                             dem::DieStudyStart::resume(bed,
                                                        std::move(progress)));
      });
      const std::string mismatch = study.resume_mismatch();
      if (!mismatch.empty())
        reject_entry(entry, file, mismatch);
      try
        {
          BranchStateWriter::verify(old_folder, files);
        }
      catch (const std::exception &e)
        {
          reject_entry(entry, file, e.what());
        }
      return {std::move(study),
              origin("Resuming from ", file, bed),
              std::move(rows),
              std::move(files),
              old_folder};
    }

    /// last_converged.h5: the state a failed run stopped at, and why.
    void
    write_last_converged(const std::filesystem::path &folder,
                         const coupling::DieInput    &input,
                         const dem::DieStudyResult   &result)
    {
      coupling::write_die_state((folder / "last_converged.h5").string(),
                                input.state_parameters,
                                *result.last_converged,
                                result.failure);
    }

    /// The solver's work and the run's wall time since @p started.
    void
    report_solver(const dem::SolverWork                      &t,
                  const std::chrono::steady_clock::time_point started)
    {
      const double seconds = dem::seconds_since(started);
      std::cout << std::defaultfloat << std::setprecision(4)
                << "Solver: " << t.iterations << " Newton iterations ("
                << t.cg_iterations << " CG), " << t.fire_iterations
                << " relaxation iterations (FIRE or L-BFGS), ";
      // A run without assemblies prints no zeros.
      if (t.assemblies > 0)
        std::cout << t.assemblies << " assemblies (" << t.assembly_seconds
                  << " s), linear solves " << t.linear_seconds
                  << " s, relaxation " << t.fire_seconds << " s, ";
      std::cout << "total " << seconds << " s\n";
    }

    class DieCommand : public Command
    {
    public:
      DieCommand()
          : Command(
            {"die",
             "die compaction, unloading and ejection of a particle bed",
             "Fills a rigid cylindrical die with bonded elasto-plastic "
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
             "rho_interior, sigma_zz_interior, sigma_rr_interior, "
             "coordination_interior, the solid fraction, the axial and "
             "radial Love-Weber stress [Pa, tension positive] and the "
             "coordination number of the region farther than two "
             "mean diameters from the die wall and both punches, each "
             "sphere counted by the part of its volume inside, nan "
             "when it holds none; its wall time per row goes to "
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
             "die_material1_6512.prm and die_material2_6512.prm."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        coupling::declare_die_parameters(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        prepare_study(coupling::get_die_input(prm));
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        return run_die(prm, folder).code;
      }
    };
  } // namespace

  DieRun
  run_die(dealii::ParameterHandler &prm, const std::filesystem::path &folder)
  {
    const coupling::DieInput input    = coupling::get_die_input(prm);
    const auto               started  = std::chrono::steady_clock::now();
    PreparedStudy            prepared = prepare_study(input);
    if (!prepared.origin.empty())
      std::cout << prepared.origin << std::endl;

    std::ofstream csv(folder / "die.csv");
    KillSwitch    kill_switch(csv.rdbuf());
    std::ostream  rows(&kill_switch);
    dem::DieCompaction::write_csv_header(rows);
    for (const auto &row : prepared.taken_over)
      dem::DieCompaction::write_csv_row(rows, row);
    rows.flush();
    BranchStateWriter branch_states(folder, input.state_parameters);
    if (!prepared.old_folder.empty())
      try
        {
          branch_states.carry_over(prepared.old_folder, prepared.branch_files);
        }
      catch (const std::exception &e)
        {
          reject_entry("Protocol/Resume from", input.resume_from, e.what());
        }

    const auto            checkpoint = folder / "checkpoints" / "compaction.h5";
    dem::DieStudyObserver observer;
    observer.progress
      = [](const std::string &line) { std::cout << line << std::endl; };
    observer.row = [&rows](const dem::DieRecord &row) {
      dem::DieCompaction::write_csv_row(rows, row);
      rows.flush();
    };
    observer.branch_state = [&branch_states](const dem::Bed    &state,
                                             const std::string &stage,
                                             const int          branch) {
      branch_states(state, stage, branch);
    };
    observer.checkpoint
      = [&](const dem::Bed &state, const dem::DieProgress &progress) {
          coupling::write_die_checkpoint(checkpoint.string(),
                                         input.resume_parameters,
                                         state,
                                         progress,
                                         branch_states.so_far());
        };
    DieRun run;
    run.result = coupling::naming_final_density(input.study, [&] {
      return prepared.study.run(observer);
    });
    const dem::DieStudyResult &result = run.result;

    if (result.stopped)
      std::cout << "Stopped as asked; continue with\n  set Resume "
                   "from = <OUTDIR>/checkpoints/compaction.h5\nin "
                   "subsection Protocol."
                << std::endl;
    if (!result.converged)
      {
        std::cerr << "compax die: " << result.failure
                  << "; the converged steps are kept in die.csv and the "
                     "last converged state in last_converged.h5\n";
        write_last_converged(folder, input, result);
        run.code = not_converged;
      }
    rows.flush();
    csv.close();
    write_die_outputs(folder, result);
    report_solver(result.solver, started);
    return run;
  }

  std::unique_ptr<Command>
  make_die_command()
  {
    return std::make_unique<DieCommand>();
  }
} // namespace compax::cli

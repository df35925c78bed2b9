#include "apps/rve/rve_run.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/gnuplot.h"
#include "apps/rve/rve_snapshot.h"
#include "apps/rve/rve_tables.h"
#include "coupling/rve_archive.h"
#include "dem/analysis/jamming_fit.h"
#include "dem/io/particle_vtu.h"
#include "dem/wall_clock.h"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <utility>

namespace compax::cli
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
    using dem::seconds_since;

    bool
    every(const int interval, const int k)
    {
      return interval > 0 && k % interval == 0;
    }

    void
    plot(const std::filesystem::path &folder, const bool with_moduli)
    {
      render_png(folder,
                 "stress_strain.gp",
                 "set datafile separator ','\nset datafile columnheaders\n"
                 "set key top left\n"
                 "set xlabel 'compressive axial log strain -eps_{zz} [-]'\n"
                 "set ylabel 'compressive stress [MPa]'\n"
                 "plot 'rve.csv' using (-column('eps_zz')):"
                 "(-column('sigma_zz')/1e6) with linespoints pt 7 ps 0.4 "
                 "title '-sigma_{zz}', '' using (-column('eps_zz')):"
                 "(-column('sigma_xx')/1e6) with linespoints pt 6 ps 0.4 "
                 "title '-sigma_{xx}', '' using (-column('eps_zz')):"
                 "(-column('sigma_yy')/1e6) with linespoints pt 4 ps 0.4 "
                 "title '-sigma_{yy}'\n",
                 "stress_strain.png");
      if (!with_moduli)
        return;
      render_png(folder,
                 "moduli.gp",
                 "set datafile separator ','\nset datafile columnheaders\n"
                 "set key top left\nset multiplot layout 1,2\n"
                 "set xlabel 'relative density [-]'\n"
                 "set ylabel 'elastic (unloading) moduli [GPa]'\n"
                 "plot 'moduli.csv' using 'relative_density':"
                 "(column('E')/1e9) with linespoints pt 7 ps 0.5 title "
                 "'E (isotropic)', '' using 'relative_density':"
                 "(column('E_z')/1e9) with linespoints pt 6 ps 0.5 title "
                 "'E_z', '' using 'relative_density':(column('E_p')/1e9) "
                 "with linespoints pt 4 ps 0.5 title 'E_p'\n"
                 "set ylabel 'consistent tangent C_{33} [GPa]'\n"
                 "plot 'moduli.csv' using 'relative_density':"
                 "(column('C33')/1e9) with linespoints pt 7 ps 0.5 title "
                 "'condensed', '' using 'relative_density':"
                 "(column('C33_affine')/1e9) with linespoints pt 6 ps 0.5 "
                 "title 'affine'\nunset multiplot\n",
                 "moduli.png");
    }

    std::string
    fixed(double value, int digits)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(digits) << value;
      return s.str();
    }
  } // namespace

  RvePathOutput::RvePathOutput(const coupling::RveStudy &study,
                               std::filesystem::path     folder,
                               const RveProgress        *resumed)
      : study(study)
      , folder(std::move(folder))
      , started(Clock::now())
  {
    if (!resumed)
      return;
    earlier = *resumed;
    // Snapshots of the earlier part, from the checkpoint's run folder
    // (read_rve_checkpoint() checked that they are there).
    const auto old_folder = std::filesystem::absolute(study.resume_from)
                              .parent_path()
                              .parent_path();
    for (const int s : resumed->snapshots)
      {
        std::filesystem::create_directories(this->folder / "snapshots");
        std::filesystem::copy_file(
          old_folder / snapshot_name(s),
          this->folder / snapshot_name(s),
          std::filesystem::copy_options::overwrite_existing);
        snapshots.push_back(s);
      }
    if (!snapshots.empty())
      write_snapshot_list();
  }

  RveProgress
  RvePathOutput::progress(const dem::RvePathResult &result,
                          const dem::RvePathState  &state) const
  {
    RveProgress p;
    p.rows   = earlier.rows;
    p.moduli = earlier.moduli;
    for (const auto &s : result.steps)
      p.rows.push_back(rve_row(s));
    for (const auto &m : result.moduli)
      p.moduli.push_back(moduli_row(m));
    p.snapshots          = snapshots;
    p.timing             = timing_rows(result);
    p.loaded_deformation = state.loaded_deformation;
    return p;
  }

  void
  RvePathOutput::write_snapshot_list() const
  {
    std::vector<std::pair<double, std::string>> list;
    for (const int s : snapshots)
      list.emplace_back(s, snapshot_name(s));
    dem::write_pvd(folder / "snapshots.pvd", list);
  }

  void
  RvePathOutput::snapshot(const int step, const dem::PeriodicBed &bed)
  {
    std::filesystem::create_directories(folder / "snapshots");
    write_rve_vtu(folder / snapshot_name(step), bed);
    snapshots.push_back(step);
    write_snapshot_list();
  }

  void
  RvePathOutput::report(const dem::RvePathStepEvent &e) const
  {
    const auto        &s       = e.state;
    const auto        &timing  = e.timings;
    const bool         unload  = e.step.unloading;
    const int          n_steps = study.steps;
    std::ostringstream left;
    if (!unload && timing.n_steps > 0)
      left << "~"
           << fixed(timing.steps / timing.n_steps * (n_steps - s.loading_done),
                    1)
           << " s (loading)";
    else
      left << "-";
    std::cout << "step " << e.step.step
              << (unload ? " unloading " : " loading ")
              << (unload ? std::to_string(s.unloading_done)
                         : std::to_string(s.loading_done) + "/"
                             + std::to_string(n_steps))
              << "  rho " << fixed(e.step.relative_density, 4) << "  sigma_zz "
              << fixed(e.step.stress(2, 2) / 1e6, 3) << " MPa  p "
              << fixed(-e.step.stress.trace() / 3.0 / 1e6, 3)
              << " MPa  iterations " << e.step.solve->iterations << "  elapsed "
              << fixed(seconds_since(started), 1) << " s  left " << left.str()
              << std::endl;
  }

  dem::RvePathObserver
  RvePathOutput::observer()
  {
    dem::RvePathObserver o;
    o.step  = [this](const dem::RvePathStepEvent &e) { report(e); };
    o.state = [this](const dem::RvePathStateEvent &e) {
      const int step = e.state.step();
      if (study.snapshot_interval > 0
          && (e.initial || every(study.snapshot_interval, step)
              || e.end_of_stage))
        snapshot(step, e.state.bed);
      if (!e.initial && (every(study.checkpoint_interval, step) || e.stopping))
        write_rve_checkpoint(folder / "checkpoints" / "rve.h5",
                             study,
                             e.state.bed,
                             progress(e.result, e.state));
    };
    o.note
      = [](const std::string &note) { std::cout << "  " << note << std::endl; };
    return o;
  }

  namespace
  {
    /**
     * jamming.csv of a uniaxial compaction: Eq. (14) fitted to the loading
     * states as the die fits it (fit_jamming), the cell's -sigma_zz standing
     * for the punch pressure and the die's pressure resolution (the force
     * floor fraction of the jamming pressure). Empty cells when it cannot be
     * fitted. Returns the fit for the log.
     */
    std::optional<dem::CoordinationFit>
    write_jamming_fit(const std::filesystem::path &file,
                      const coupling::RveStudy    &study,
                      const RveProgress           &p)
    {
      std::vector<dem::CompactionState> states;
      for (const std::vector<double> &row : p.rows)
        if (row[rve_column("stage")] == 0.0 && row[rve_column("step")] > 0.0)
          states.push_back({row[rve_column("relative_density")],
                            -row[rve_column("sigma_zz")],
                            row[rve_column("coordination_number")]});
      const double resolution
        = study.loading.force_floor_fraction * study.loading.jamming_pressure;
      const auto    fit = dem::fit_jamming(states, resolution);
      std::ofstream out(file);
      out << "rho_c_Z,Z_c,Z_0,theta,rms,jammed_states\n"
          << std::setprecision(12);
      const std::size_t jammed = dem::jammed_states(states, resolution).size();
      if (fit)
        out << fit->rho_c << ',' << fit->Z_c << ',' << fit->Z_0 << ','
            << fit->theta << ',' << fit->rms << ',' << jammed << '\n';
      else
        out << ",,,,," << jammed << '\n';
      if (!out)
        throw std::runtime_error("cannot write " + file.string());
      return fit;
    }
  } // namespace

  RveOutcome
  RvePathOutput::finish(const dem::RvePathResult &result,
                        const dem::RvePathStudy  &path)
  {
    RveOutcome out;
    out.stopped     = result.stopped;
    out.timings     = result.timings;
    const auto &bed = path.state().bed;
    if (!result.converged)
      {
        std::cerr << "compax rve: " << result.failure
                  << "; the converged steps are kept in rve.csv and the last "
                     "converged state in last_converged.h5\n";
        coupling::save_rve((folder / "last_converged.h5").string(),
                           bed,
                           study.resume_parameters);
        out.code = not_converged;
      }
    const RveProgress p = progress(result, path.state());
    // The final state as a checkpoint too: a resumed run's output holds
    // what the uninterrupted run's does.
    if (study.checkpoint_interval > 0 && out.code == success && !out.stopped)
      write_rve_checkpoint(folder / "checkpoints" / "rve.h5", study, bed, p);

    write_table(folder / "rve.csv", rve_columns(), p.rows);
    write_table(folder / "moduli.csv", moduli_columns(), p.moduli);
    write_table(folder / "timing.csv", timing_columns(), p.timing);
    plot(folder, !study.elastic);
    if (study.path == dem::RveStrainPath::uniaxial && !study.elastic)
      if (const auto fit = write_jamming_fit(folder / "jamming.csv", study, p))
        std::cout << "Eq. 14 on the uniaxial compaction: rho_c_Z "
                  << fixed(fit->rho_c, 4) << ", Z_c " << fixed(fit->Z_c, 3)
                  << ", theta " << fixed(fit->theta, 3) << std::endl;
    const auto &timing = result.timings;
    out.timings.total  = seconds_since(started);
    std::cout << "Cell of " << bed.particles.size()
              << " particles: " << timing.n_steps << " steps, "
              << fixed(timing.n_steps ? timing.steps / timing.n_steps : 0.0, 4)
              << " s per step; " << timing.n_tangents << " condensed tangents, "
              << fixed(timing.n_tangents ? timing.tangents / timing.n_tangents
                                         : 0.0,
                       4)
              << " s each";
    if (timing.n_fd_tangents > 0)
      std::cout << "; " << timing.n_fd_tangents
                << " finite-difference tangents, "
                << fixed(timing.fd_tangents / timing.n_fd_tangents, 4)
                << " s each";
    std::cout << "; total " << fixed(out.timings.total, 2) << " s" << std::endl;
    if (out.stopped)
      std::cout << "Stopped as asked; continue with\n  set Resume from = "
                   "<OUTDIR>/checkpoints/rve.h5\nin subsection Checkpoints."
                << std::endl;
    return out;
  }

  RveOutcome
  run_rve_path(const coupling::RveStudy    &study,
               dem::PeriodicBed             bed,
               const std::filesystem::path &folder,
               const RveProgress           *resumed)
  {
    RvePathOutput     output(study, folder, resumed);
    dem::RvePathState state = resumed
                                ? resumed_state(std::move(bed),
                                                *resumed,
                                                study.loading.jamming_pressure)
                                : dem::RvePathState{std::move(bed)};
    if (resumed)
      std::cout << "Resuming from " << study.resume_from << " at step "
                << resumed->rows.size() - 1 << " (relative density "
                << state.bed.relative_density() << ")" << std::endl;
    dem::RvePathStudy path(study.model, study, std::move(state));
    return output.finish(path.run(output.observer()), path);
  }
} // namespace compax::cli

#include "apps/rve/rve_run.h"

#include "apps/cli/archive_entry.h"
#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/common/gnuplot.h"
#include "apps/common/voigt_columns.h"
#include "dem/rve/rve_measures.h"
#include "apps/rve/rve_snapshot.h"
#include "coupling/elastic_moduli.h"
#include "coupling/rve_archive.h"
#include "dem/io/particle_vtu.h"
#include "dem/rve/periodic_bed_system.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace compax::cli
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    using Clock = std::chrono::steady_clock;

    double
    seconds_since(const Clock::time_point t)
    {
      return std::chrono::duration<double>(Clock::now() - t).count();
    }

    std::size_t
    index_of(const std::vector<std::string> &names, const std::string &name)
    {
      const auto it = std::find(names.begin(), names.end(), name);
      if (it == names.end())
        throw std::logic_error("no column '" + name + "'");
      return it - names.begin();
    }

    /// Writes rows of numbers; "stage" as text, NaN as an empty cell.
    void
    write_table(const std::filesystem::path            &file,
                const std::vector<std::string>         &columns,
                const std::vector<std::vector<double>> &rows)
    {
      CsvWriter         csv(file, columns);
      const std::size_t stage = index_of(columns, "stage");
      for (const auto &row : rows)
        {
          for (std::size_t k = 0; k < columns.size(); ++k)
            if (k == stage)
              csv << std::string(row[k] == 0.0 ? "loading" : "unloading");
            else if (std::isnan(row[k]))
              csv.empty();
            else if (columns[k] == "step" || columns[k] == "iterations"
                     || columns[k] == "substeps" || columns[k] == "cutbacks"
                     || columns[k] == "bonds" || columns[k] == "bonds_formed"
                     || columns[k] == "bonds_broken" || columns[k] == "jammed")
              csv << static_cast<long long>(row[k]);
            else
              csv << row[k];
          csv.end_row();
        }
      csv.close();
    }

    /// The symmetric part of a tangent (Cauchy-stress tangents carry a
    /// non-symmetric -sigma tr(eps) term); the elastic constants are read
    /// from it.
    dem::Matrix6d
    symmetric(const dem::Matrix6d &C)
    {
      return 0.5 * (C + C.transpose());
    }

    /// C11 C33 C12 C13 C44 of the transversely isotropic part of C.
    std::array<double, 5>
    ti_entries(const dem::Matrix6d &C)
    {
      const auto P = coupling::transversely_isotropic_projection(symmetric(C));
      return {P(0, 0), P(2, 2), P(0, 1), P(0, 2), P(3, 3)};
    }

    std::vector<double>
    flatten(const std::vector<std::vector<double>> &rows, std::size_t width)
    {
      std::vector<double> v;
      v.reserve(rows.size() * width);
      for (const auto &r : rows)
        v.insert(v.end(), r.begin(), r.end());
      return v;
    }

    std::vector<std::vector<double>>
    unflatten(const std::vector<double> &v, std::size_t width)
    {
      if (width == 0 || v.size() % width != 0)
        throw std::runtime_error("malformed table");
      std::vector<std::vector<double>> rows;
      for (std::size_t k = 0; k < v.size(); k += width)
        rows.emplace_back(v.begin() + k, v.begin() + k + width);
      return rows;
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
    snapshot_name(const int step)
    {
      return "snapshots/rve-" + std::to_string(step) + ".vtu";
    }

    std::string
    fixed(double value, int digits)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(digits) << value;
      return s.str();
    }
  } // namespace

  const std::vector<std::string> &
  rve_columns()
  {
    static const std::vector<std::string> names = [] {
      std::vector<std::string> n{"step", "stage", "relative_density"};
      for (const char *tensor : {"eps", "sigma"})
        for (std::string &column : voigt_columns(tensor))
          n.push_back(std::move(column));
      n.insert(n.end(),
               {"mean_pressure",
                "coordination_number",
                "coordination_without_rattlers",
                "rattler_fraction",
                "bonding_surface",
                "bonds",
                "bonds_formed",
                "bonds_broken",
                "jammed",
                "substeps",
                "cutbacks",
                "iterations",
                "residual"});
      return n;
    }();
    return names;
  }

  const std::vector<std::string> &
  moduli_columns()
  {
    static const std::vector<std::string> names = [] {
      std::vector<std::string> n{"step",
                                 "stage",
                                 "relative_density",
                                 "E",
                                 "nu",
                                 "bulk_modulus",
                                 "shear_modulus",
                                 "E_p",
                                 "nu_p",
                                 "E_z",
                                 "nu_zp",
                                 "G_zp"};
      // The transversely isotropic stiffness, tangent and affine.
      for (const std::string variant : {"", "_affine"})
        for (const char *component : {"C11", "C33", "C12", "C13", "C44"})
          n.push_back(component + variant);
      n.push_back("tangent_fd_error");
      return n;
    }();
    return names;
  }

  std::size_t
  rve_column(const std::string &name)
  {
    return index_of(rve_columns(), name);
  }

  std::size_t
  moduli_column(const std::string &name)
  {
    return index_of(moduli_columns(), name);
  }

  const std::vector<std::string> &
  timing_columns()
  {
    static const std::vector<std::string> names{"step",
                                                "stage",
                                                "step_seconds",
                                                "tangent_seconds"};
    return names;
  }

  void
  write_rve_checkpoint(const std::filesystem::path &file,
                       const RveStudy              &study,
                       const dem::PeriodicBed      &bed,
                       const RveProgress           &p)
  {
    std::filesystem::create_directories(file.parent_path());
    coupling::Hdf5ArchiveWriter archive(file.string(),
                                        {coupling::archive_kind::rve,
                                         study.resume_parameters});
    coupling::save_rve(archive, "rve", bed);
    archive.write_array("rows",
                        flatten(p.rows, rve_columns().size()),
                        {p.rows.size(), rve_columns().size()});
    archive.write_array("moduli",
                        flatten(p.moduli, moduli_columns().size()),
                        {p.moduli.size(), moduli_columns().size()});
    archive.write_array("snapshots",
                        std::vector<double>(p.snapshots.begin(),
                                            p.snapshots.end()));
    // The snapshots so far, by content: a resumed run takes them over.
    std::string hashes;
    for (const int s : p.snapshots)
      hashes
        += coupling::file_hash(
             (file.parent_path().parent_path() / snapshot_name(s)).string())
           + "\n";
    archive.write_text("snapshot_hashes", hashes);
    std::vector<double> F(9);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        F[3 * r + c] = p.loaded_deformation(r, c);
    archive.write_array("loaded_deformation", F, {3, 3});
    archive.commit();
  }

  RveProgress
  read_rve_checkpoint(const std::string &file,
                      const RveStudy    &study,
                      dem::PeriodicBed  &bed)
  {
    const std::string entry = "Checkpoints/Resume from";
    RveProgress       p;
    read_archive_entry(entry, file, coupling::archive_kind::rve, [&] {
      const coupling::Hdf5ArchiveReader archive(file,
                                                coupling::archive_kind::rve,
                                                study.resume_parameters);
      bed    = coupling::load_rve(archive, "rve", study.model);
      p.rows = unflatten(archive.read_array("rows"), rve_columns().size());
      p.moduli
        = unflatten(archive.read_array("moduli"), moduli_columns().size());
      for (const double s : archive.read_array("snapshots"))
        {
          if (!(s >= 0 && s <= 1e9))
            throw std::runtime_error("malformed snapshot list");
          p.snapshots.push_back(static_cast<int>(s));
        }
      std::istringstream hashes(archive.read_text("snapshot_hashes"));
      for (std::string h; std::getline(hashes, h);)
        p.snapshot_hashes.push_back(h);
      if (p.snapshot_hashes.size() != p.snapshots.size())
        throw std::runtime_error("malformed snapshot list");
      const auto F = archive.read_array("loaded_deformation");
      if (F.size() != 9)
        throw std::runtime_error("malformed loaded deformation");
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          p.loaded_deformation(r, c) = F[3 * r + c];
      if (p.rows.empty())
        throw std::runtime_error("no rows");
      for (const auto &row : p.rows)
        if (!(row[rve_column("step")] >= 0 && row[rve_column("step")] <= 1e9))
          throw std::runtime_error("malformed rows");
    });
    // The snapshots of the earlier part, next to the checkpoint.
    const auto old_folder
      = std::filesystem::absolute(file).parent_path().parent_path();
    for (std::size_t k = 0; k < p.snapshots.size(); ++k)
      {
        const auto from = old_folder / snapshot_name(p.snapshots[k]);
        if (!std::filesystem::is_regular_file(from))
          reject_entry(entry,
                       file,
                       "the earlier snapshot '" + snapshot_name(p.snapshots[k])
                         + "' is not next to the checkpoint (in '"
                         + old_folder.string()
                         + "'); resume from the checkpoint in its run folder");
        if (coupling::file_hash(from.string()) != p.snapshot_hashes[k])
          reject_entry(entry,
                       file,
                       "the earlier snapshot '" + from.string()
                         + "' differs from the one the checkpoint lists "
                           "(changed since)");
      }
    return p;
  }

  RveOutcome
  run_rve_path(const RveStudy              &study,
               dem::PeriodicBed             bed,
               const std::filesystem::path &folder,
               const RveProgress           *resumed)
  {
    const auto          started = Clock::now();
    RveOutcome          out;
    RveProgress        &progress        = out.progress;
    RveTimings         &timing          = out.timings;
    const auto         &model           = study.model;
    const std::size_t   n_rve           = rve_columns().size();
    const std::size_t   n_mod           = moduli_columns().size();
    const std::size_t   c_stage         = rve_column("stage");
    const std::size_t   c_rho           = rve_column("relative_density");
    const std::size_t   c_szz           = rve_column("sigma_zz");
    const std::size_t   c_p             = rve_column("mean_pressure");
    const auto          checkpoint      = folder / "checkpoints" / "rve.h5";
    const auto          snapshot_folder = folder / "snapshots";
    const std::uint64_t n_particles     = bed.particles.size();

    auto loading = std::make_unique<dem::RveLoading>(model, study.loading);
    // Elastic spheres (Hertz or nonlocal): their own stepper, stress and
    // coordination; no tangents.
    std::unique_ptr<dem::NonlocalRveLoading> elastic;
    if (study.elastic)
      elastic = std::make_unique<dem::NonlocalRveLoading>(*study.elastic);
    // F_k F_{k-1}^{-1} - I of the last step (the direction of the trial
    // state of a finite-difference check).
    Eigen::Matrix3d last_increment = Eigen::Matrix3d::Zero();
    auto            tangent        = std::make_unique<dem::TangentCalculator>();
    dem::EquilibriumOptions fd_options = study.loading.equilibrium;
    fd_options.force_tolerance
      = std::min(fd_options.force_tolerance, study.fd_force_tolerance);
    fd_options.step_tolerance
      = std::min(fd_options.step_tolerance, study.fd_force_tolerance);

    // One row of rve.csv for the current state.
    const auto record = [&](int                       step,
                            bool                      unloading,
                            const dem::RveStepResult *r,
                            double                    step_seconds) {
      std::vector<double>   row(n_rve, nan);
      const Eigen::Matrix3d eps = dem::logarithmic_strain(bed.deformation);
      const Eigen::Matrix3d sigma
        = elastic ? elastic->stress(bed) : dem::love_weber_stress(bed);
      dem::RveMeasures m;
      if (elastic)
        {
          m.coordination_number           = elastic->coordination(bed);
          m.coordination_without_rattlers = nan;
          m.rattler_fraction              = nan;
        }
      else
        m = dem::measure_rve(bed);
      auto set = [&](const char *name, double v) { row[rve_column(name)] = v; };
      set("step", step);
      set("stage", unloading ? 1.0 : 0.0);
      set("relative_density", bed.relative_density());
      set("eps_xx", eps(0, 0));
      set("eps_yy", eps(1, 1));
      set("eps_zz", eps(2, 2));
      set("eps_yz", eps(1, 2));
      set("eps_xz", eps(0, 2));
      set("eps_xy", eps(0, 1));
      set("sigma_xx", sigma(0, 0));
      set("sigma_yy", sigma(1, 1));
      set("sigma_zz", sigma(2, 2));
      set("sigma_yz", 0.5 * (sigma(1, 2) + sigma(2, 1)));
      set("sigma_xz", 0.5 * (sigma(0, 2) + sigma(2, 0)));
      set("sigma_xy", 0.5 * (sigma(0, 1) + sigma(1, 0)));
      set("mean_pressure", -sigma.trace() / 3.0);
      set("coordination_number", m.coordination_number);
      set("coordination_without_rattlers", m.coordination_without_rattlers);
      set("rattler_fraction", m.rattler_fraction);
      set("bonding_surface", m.bonding_surface);
      set("bonds", double(m.n_bonds));
      set("bonds_formed", r ? double(r->bonds.formed) : 0.0);
      set("bonds_broken", r ? double(r->bonds.broken) : 0.0);
      set("jammed", r ? double(r->jammed) : 0.0);
      set("substeps", r ? r->substeps : 0);
      set("cutbacks", r ? r->cutbacks : 0);
      set("iterations", r ? r->iterations : 0);
      set("residual", r ? r->relative_residual : 0.0);
      progress.rows.push_back(row);
      progress.timing.push_back(
        {double(step), unloading ? 1.0 : 0.0, step_seconds, nan});
    };

    // Tangents and moduli at the current state (jammed cells only: a loose
    // cell has no stiffness); the finite-difference check if asked.
    const auto moduli = [&](int step, bool unloading, bool check) {
      // A loose cell has no stiffness; a bonded cell in tension has. The
      // condensed tangent is that of the bonded law.
      if (elastic
          || std::abs(dem::mean_pressure(bed)) < study.loading.jamming_pressure)
        return;
      std::vector<double> row(n_mod, nan);
      auto                set
        = [&](const char *name, double v) { row[moduli_column(name)] = v; };
      const auto              t0 = Clock::now();
      const dem::CellTangents current
        = tangent->compute(bed, model, dem::ContactBranch::current);
      const double seconds = seconds_since(t0);
      timing.tangents += seconds;
      ++timing.n_tangents;
      const dem::CellTangents elastic
        = tangent->compute(bed, model, dem::ContactBranch::unloading);
      set("step", step);
      set("stage", unloading ? 1.0 : 0.0);
      set("relative_density", bed.relative_density());
      const auto iso
        = coupling::isotropic_projection(symmetric(elastic.condensed));
      set("E", iso.youngs_modulus);
      set("nu", iso.poisson_ratio);
      set("bulk_modulus", iso.bulk_modulus);
      set("shear_modulus", iso.shear_modulus);
      try
        {
          const auto ti = coupling::transversely_isotropic_moduli(
            symmetric(elastic.condensed));
          set("E_p", ti.youngs_in_plane);
          set("nu_p", ti.poisson_in_plane);
          set("E_z", ti.youngs_axial);
          set("nu_zp", ti.poisson_axial_to_plane);
          set("G_zp", ti.shear_axial);
        }
      catch (const std::domain_error &)
        {
          // Not positive definite (a barely jammed cell): left empty.
        }
      const auto  c        = ti_entries(current.condensed);
      const auto  a        = ti_entries(current.affine);
      const char *names[5] = {"C11", "C33", "C12", "C13", "C44"};
      for (int k = 0; k < 5; ++k)
        {
          set(names[k], c[k]);
          row[moduli_column(std::string(names[k]) + "_affine")] = a[k];
        }
      if (!progress.timing.empty() && progress.timing.back()[0] == step)
        progress.timing.back()[3] = seconds;
      if (check)
        {
          // At a trial state half a step further along the path,
          // equilibrated with frozen histories: a converged state puts
          // every loading contact on the kink between its plastic and
          // elastic branches, where a central difference approximates
          // neither; past it each contact is strictly on one branch.
          const auto       t1    = Clock::now();
          dem::PeriodicBed trial = bed;
          map_affinely(trial,
                       (Eigen::Matrix3d::Identity() + 0.5 * last_increment)
                         * bed.deformation);
          dem::PeriodicAssembler assembler;
          dem::PeriodicBedSystem system(trial, model, assembler);
          dem::TrustRegionNewton newton(fd_options);
          const bool             ok = newton.solve(system).converged;
          try
            {
              if (!ok)
                throw std::runtime_error("the trial state did not converge");
              const dem::Matrix6d c
                = dem::TangentCalculator()
                    .compute(trial, model, dem::ContactBranch::current)
                    .condensed;
              const dem::Matrix6d fd = dem::finite_difference_tangent(
                trial, model, study.fd_strain_step, fd_options);
              set("tangent_fd_error", (c - fd).norm() / fd.norm());
            }
          catch (const std::runtime_error &e)
            {
              std::cout << "  finite-difference check skipped: " << e.what()
                        << std::endl;
            }
          timing.fd_tangents += seconds_since(t1);
          ++timing.n_fd_tangents;
        }
      progress.moduli.push_back(row);
    };

    const auto write_tables = [&] {
      write_table(folder / "rve.csv", rve_columns(), progress.rows);
      write_table(folder / "moduli.csv", moduli_columns(), progress.moduli);
      write_table(folder / "timing.csv", timing_columns(), progress.timing);
    };

    const auto write_snapshot_list = [&] {
      std::vector<std::pair<double, std::string>> list;
      for (const int s : progress.snapshots)
        list.emplace_back(s, snapshot_name(s));
      dem::write_pvd(folder / "snapshots.pvd", list);
    };
    const auto snapshot = [&](int step) {
      std::filesystem::create_directories(snapshot_folder);
      write_rve_vtu(folder / snapshot_name(step), bed);
      progress.snapshots.push_back(step);
      write_snapshot_list();
    };

    int loading_done = 0, unloading_done = 0;
    if (resumed)
      {
        progress = *resumed;
        for (const auto &row : progress.rows)
          if (row[rve_column("step")] > 0)
            (row[c_stage] == 0.0 ? loading_done : unloading_done) += 1;
        // Snapshots of the earlier part, from the checkpoint's run folder
        // (read_rve_checkpoint() checked that they are there).
        const auto old_folder = std::filesystem::absolute(study.resume_from)
                                  .parent_path()
                                  .parent_path();
        std::vector<int> kept;
        for (const int s : progress.snapshots)
          {
            std::filesystem::create_directories(snapshot_folder);
            std::filesystem::copy_file(
              old_folder / snapshot_name(s),
              folder / snapshot_name(s),
              std::filesystem::copy_options::overwrite_existing);
            kept.push_back(s);
          }
        progress.snapshots = kept;
        if (!progress.snapshots.empty())
          write_snapshot_list();
        std::cout << "Resuming from " << study.resume_from << " at step "
                  << progress.rows.size() - 1 << " (relative density "
                  << bed.relative_density() << ")" << std::endl;
      }
    else
      {
        record(0, false, nullptr, 0.0);
        moduli(0, false, false);
        if (study.snapshot_interval > 0)
          snapshot(0);
      }
    const double rho0 = progress.rows.front()[c_rho];
    // A fresh loading (at the start, after a checkpoint, on resumption)
    // takes over the sticky jamming of the path so far: jammed if a
    // recorded state carried the jamming pressure.
    const auto keep_jammed = [&]() {
      for (const auto &row : progress.rows)
        if (row[c_p] >= study.loading.jamming_pressure)
          {
            loading->set_jammed();
            return;
          }
    };
    keep_jammed();

    int        step = static_cast<int>(progress.rows.size()) - 1;
    const auto every
      = [](int interval, int k) { return interval > 0 && k % interval == 0; };
    const auto after_step = [&](bool unloading, bool end_of_stage) {
      const bool check = every(study.fd_interval, step);
      if (every(study.tangent_interval, step) || end_of_stage || check)
        moduli(step, unloading, check);
      if (every(study.snapshot_interval, step) || end_of_stage)
        if (study.snapshot_interval > 0)
          snapshot(step);
      const bool stop = study.stop_after > 0 && step >= study.stop_after;
      if (every(study.checkpoint_interval, step) || stop)
        write_rve_checkpoint(checkpoint, study, bed, progress);
      // Every step starts afresh from the state a checkpoint would hold, as
      // a resumed run does: the results depend neither on the checkpoint
      // interval nor on where a run was stopped and resumed.
      bed.contacts.rebuild(bed.particles, bed.cell, model);
      loading = std::make_unique<dem::RveLoading>(model, study.loading);
      keep_jammed();
      tangent = std::make_unique<dem::TangentCalculator>();
      if (study.elastic)
        elastic = std::make_unique<dem::NonlocalRveLoading>(*study.elastic);
      return stop;
    };

    // Progress on screen.
    const int  loading_steps = study.steps;
    const auto report        = [&](bool unloading) {
      const auto        &row     = progress.rows.back();
      const double       elapsed = seconds_since(started);
      std::ostringstream left;
      if (!unloading && timing.n_steps > 0)
        left << "~"
             << fixed(timing.steps / timing.n_steps
                        * (loading_steps - loading_done),
                      1)
             << " s (loading)";
      else
        left << "-";
      std::cout << "step " << step << (unloading ? " unloading " : " loading ")
                << (unloading ? std::to_string(unloading_done)
                                     : std::to_string(loading_done) + "/"
                                  + std::to_string(loading_steps))
                << "  rho " << fixed(row[c_rho], 4) << "  sigma_zz "
                << fixed(row[c_szz] / 1e6, 3) << " MPa  p "
                << fixed(row[c_p] / 1e6, 3) << " MPa  iterations "
                << static_cast<int>(row[rve_column("iterations")])
                << "  elapsed " << fixed(elapsed, 1) << " s  left "
                << left.str() << std::endl;
    };

    // One step to F (or by a strain increment); false if it failed.
    const auto advance = [&](bool                   unloading,
                             const Eigen::Matrix3d &target,
                             const Eigen::Matrix3d *increment) {
      const auto               t0     = Clock::now();
      const Eigen::Matrix3d    F_prev = bed.deformation;
      const dem::RveStepResult r
        = elastic ? (increment ? elastic->apply_strain(bed, *increment)
                               : elastic->deform_to(bed, target))
                  : (increment ? loading->apply_strain(bed, *increment)
                               : loading->deform_to(bed, target));
      const double seconds = seconds_since(t0);
      if (!r.converged)
        return false;
      last_increment
        = bed.deformation * F_prev.inverse() - Eigen::Matrix3d::Identity();
      timing.steps += seconds;
      ++timing.n_steps;
      ++step;
      (unloading ? unloading_done : loading_done) += 1;
      record(step, unloading, &r, seconds);
      return true;
    };

    const auto fail = [&](const std::string &why) {
      std::cerr << "compax rve: " << why
                << "; the converged steps are kept in rve.csv and the last "
                   "converged state in last_converged.h5\n";
      coupling::save_rve((folder / "last_converged.h5").string(),
                         bed,
                         study.resume_parameters);
      out.code = not_converged;
    };

    const auto loading_target = [&](int k) {
      const double rho
        = rho0 + (study.target_density - rho0) * double(k) / loading_steps;
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      if (study.path == RvePath::uniaxial)
        F(2, 2) = rho0 / rho;
      else
        F *= std::cbrt(rho0 / rho);
      return F;
    };

    try
      {
        bool stop = false;
        while (!stop && loading_done < loading_steps && out.code == success)
          {
            const int  k  = loading_done + 1;
            const bool ok = study.path == RvePath::csv
                              ? advance(false, {}, &study.increments[k - 1])
                              : advance(false, loading_target(k), nullptr);
            if (!ok)
              {
                fail("loading step " + std::to_string(k) + " did not converge");
                break;
              }
            if (loading_done == loading_steps)
              progress.loaded_deformation = bed.deformation;
            report(false);
            stop = after_step(false, loading_done == loading_steps);
          }
        const auto unloaded = [&] {
          const auto &row = progress.rows.back();
          if (row[c_stage] == 0.0)
            return false;
          // Elastic spheres unload to zero stress asymptotically: the
          // relaxation of a loose cell resolves stresses down to its force
          // floor, about force_floor_fraction times the jamming pressure.
          const double resolution = elastic ? study.loading.force_floor_fraction
                                                * study.loading.jamming_pressure
                                            : 0.0;
          return study.path == RvePath::uniaxial ? row[c_szz] >= -resolution
                                                 : row[c_p] <= resolution;
        };
        while (!stop && study.unload && out.code == success
               && loading_done == loading_steps && !unloaded()
               && unloading_done < study.max_unloading_steps)
          {
            const int              u     = unloading_done + 1;
            const Eigen::Matrix3d &F_max = progress.loaded_deformation;
            Eigen::Matrix3d        F     = F_max;
            if (study.path == RvePath::uniaxial)
              F.row(2) *= std::exp(u * study.unloading_step);
            else if (study.path == RvePath::hydrostatic)
              F *= std::exp(u * study.unloading_step);
            else
              {
                if (u > loading_steps)
                  break;
                // Undo the increments in reverse order: F_{k-1} = (I +
                // eps_k)^{-1} F_k.
                F = (Eigen::Matrix3d::Identity()
                     + study.increments[loading_steps - u])
                      .inverse()
                    * bed.deformation;
              }
            if (!advance(true, F, nullptr))
              {
                fail("unloading step " + std::to_string(u)
                     + " did not converge");
                break;
              }
            report(true);
            const bool last = unloaded()
                              || unloading_done == study.max_unloading_steps
                              || (study.path == RvePath::csv
                                  && unloading_done == loading_steps);
            stop = after_step(true, last);
          }
        out.stopped = stop;
      }
    catch (const std::runtime_error &e)
      {
        fail(e.what());
      }
    // The final state as a checkpoint too: a resumed run's output holds
    // what the uninterrupted run's does.
    if (study.checkpoint_interval > 0 && out.code == success && !out.stopped)
      write_rve_checkpoint(checkpoint, study, bed, progress);

    write_tables();
    plot(folder, !study.elastic);
    timing.total = seconds_since(started);
    std::cout << "Cell of " << n_particles << " particles: " << timing.n_steps
              << " steps, "
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
    std::cout << "; total " << fixed(timing.total, 2) << " s" << std::endl;
    if (out.stopped)
      std::cout << "Stopped as asked; continue with\n  set Resume from = "
                   "<OUTDIR>/checkpoints/rve.h5\nin subsection Checkpoints."
                << std::endl;
    return out;
  }
} // namespace compax::cli

#include "dem/die/die_compaction.h"

#include "dem/numbers.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// Wall time between the progress lines of one relaxation [s].
    constexpr double relaxation_report_interval = 30.0;

    double
    now()
    {
      return std::chrono::duration<double>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
    }

    /// Restores a stream's format (flags, precision) when it goes out of
    /// scope: the progress stream is the caller's (often std::cout), and
    /// the protocol's progress lines must not leave it at precision 1.
    class FormatGuard
    {
    public:
      explicit FormatGuard(std::ostream *stream)
          : stream(stream)
      {
        if (stream)
          {
            flags     = stream->flags();
            precision = stream->precision();
          }
      }

      ~FormatGuard()
      {
        if (stream)
          {
            stream->flags(flags);
            stream->precision(precision);
          }
      }

      FormatGuard(const FormatGuard &) = delete;
      FormatGuard &
      operator=(const FormatGuard &)
        = delete;

    private:
      std::ostream           *stream;
      std::ios_base::fmtflags flags{};
      std::streamsize         precision = 0;
    };

    /**
     * Wall time the compaction steps after @p step of @p n_steps will take
     * [s], at the mean cost of the steps since the bed jammed (the rows
     * from density @p rho_jammed on; all compaction rows while none is
     * known). The loose steps before jamming cost a fraction of a jammed
     * step and the onset many, so the jammed steps alone predict the rest.
     */
    double
    compaction_seconds_left(const std::vector<DieRecord> &rows,
                            const double                  rho_jammed,
                            const int                     step,
                            const int                     n_steps,
                            const double                  elapsed)
    {
      double since = 0.0;
      int    from  = 0;
      if (rho_jammed > 0.0)
        for (const DieRecord &r : rows)
          if (r.stage == "compaction" && r.relative_density >= rho_jammed)
            {
              since = r.wall_seconds;
              from  = r.step;
              break;
            }
      const int done = step - from;
      if (done <= 0)
        return elapsed / step * (n_steps - step);
      return (elapsed - since) / done * (n_steps - step);
    }

    /// Punch gap at which the bed reaches in-die relative density rho.
    double
    gap_for(const Bed &bed, const double rho)
    {
      return bed.particles.solid_volume() / (bed.walls.punch_area() * rho);
    }

    /// Axial extent and largest radial reach of a compact's spheres [m].
    struct CompactExtent
    {
      double z_lo = 1e300, z_hi = -1e300, r_max = 0.0;
    };

    CompactExtent
    compact_extent(const ParticleSystem &p)
    {
      CompactExtent e;
      for (std::size_t i = 0; i < p.size(); ++i)
        {
          const auto &x = p.positions[i];
          e.z_lo        = std::min(e.z_lo, x[2] - p.radii[i]);
          e.z_hi        = std::max(e.z_hi, x[2] + p.radii[i]);
          e.r_max = std::max(e.r_max, std::hypot(x[0], x[1]) + p.radii[i]);
        }
      return e;
    }

    /// Angular and axial sectors of about one mean diameter on the
    /// envelope of a compact (at least 8 x 1).
    std::pair<int, int>
    envelope_sectors(const Bed &bed)
    {
      const double        d = 2.0 * bed.particles.mean_radius();
      const CompactExtent e = compact_extent(bed.particles);
      return {std::max(8, static_cast<int>(2 * pi * e.r_max / d)),
              std::max(1, static_cast<int>((e.z_hi - e.z_lo) / d))};
    }

    /**
     * Volume of the cylinder that envelops a compact: its radius is the
     * mean over angular and height sectors (about one diameter wide) of
     * the outermost sphere surface max(r_i + R_i), its height the axial
     * extent of the spheres. Averaging over sectors keeps a few protruding
     * surface spheres from widening the cylinder. The sectors are
     * n_theta x n_z (see envelope_sectors()); the same grid before and
     * after ejection, so that a moving surface sphere cannot change the
     * number of sectors and the volume by a jump.
     */
    double
    envelope_volume(const Bed &bed, const int n_theta, const int n_z)
    {
      const auto         &p    = bed.particles;
      const CompactExtent e    = compact_extent(p);
      const double        z_lo = e.z_lo, z_hi = e.z_hi, r_max = e.r_max;
      std::vector<double> outer(static_cast<std::size_t>(n_theta) * n_z, 0.0);
      for (std::size_t i = 0; i < p.size(); ++i)
        {
          const auto  &x = p.positions[i];
          const double t = (std::atan2(x[1], x[0]) + pi) / (2 * pi);
          const int    a = std::min(n_theta - 1, static_cast<int>(t * n_theta));
          const int    b
            = std::min(n_z - 1,
                       static_cast<int>((x[2] - z_lo) / (z_hi - z_lo) * n_z));
          double &o = outer[static_cast<std::size_t>(b) * n_theta + a];
          o         = std::max(o, std::hypot(x[0], x[1]) + p.radii[i]);
        }
      double sum = 0.0;
      int    n   = 0;
      for (const double o : outer)
        if (o > 0.0)
          {
            sum += o;
            ++n;
          }
      const double r = n > 0 ? sum / n : r_max;
      return pi * r * r * (z_hi - z_lo);
    }
  } // namespace

  DieCompaction::DieCompaction(Bed                 bed,
                               const ContactModel &model,
                               DieProtocol         protocol_,
                               EquilibriumOptions  equilibrium)
      : path(std::move(bed))
      , model(model)
      , protocol(std::move(protocol_))
      , equilibrium(equilibrium)
  {
    // Net forces below the tolerance times a particle's share of the
    // jamming pressure are below what the study resolves anywhere else.
    if (this->equilibrium.force_floor == 0.0)
      this->equilibrium.force_floor
        = this->equilibrium.force_tolerance
          * protocol.consolidation.jamming_pressure * pi
          * std::pow(path.particles.mean_radius(), 2);
    reset_stepper();
    auto &t = protocol.compaction_targets;
    t.insert(t.end(),
             protocol.unloading_points.begin(),
             protocol.unloading_points.end());
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(),
                        t.end(),
                        [](double a, double b) {
                          return std::abs(a - b) < 1e-12;
                        }),
            t.end());
    std::sort(protocol.unloading_points.begin(),
              protocol.unloading_points.end());
  }

  double
  DieCompaction::force_resolution() const
  {
    return pressure_resolution() * pi
           * std::pow(path.particles.mean_radius(), 2);
  }

  double
  DieCompaction::pressure_resolution() const
  {
    return protocol.consolidation.pressure_resolution();
  }

  void
  DieCompaction::reset_stepper()
  {
    if (protocol.elastic)
      {
        elastic = std::make_unique<ElasticDieStepper>(*protocol.elastic);
        return;
      }
    LoadSteppingOptions stepping;
    if (!protocol.consolidate)
      {
        const ConsolidationOptions &c      = protocol.consolidation;
        stepping.jamming_pressure          = c.jamming_pressure;
        stepping.unjammed_tolerance        = c.relative_tolerance;
        stepping.unjammed_iterations       = c.max_relaxation_iterations;
        stepping.force_resolution          = force_resolution();
        stepping.unjammed_equilibrium      = protocol.unjammed_equilibrium;
        stepping.resolved_history          = protocol.resolved_history;
        stepping.secant_predictor_unjammed = protocol.secant_predictor_unjammed;
        stepping.relax_opening_at_first_failure
          = protocol.relax_opening_at_first_failure;
      }
    stepper = std::make_unique<LoadStepper>(model, equilibrium, stepping);
    report_relaxations();
  }

  void
  DieCompaction::report_relaxations()
  {
    if (!stepper)
      return;
    RelaxationReport report; // none without a progress stream
    if (progress)
      report = [out = progress](const RelaxationProgress &p) {
        std::ostringstream line;
        line << "  relaxing: " << p.evaluations << " residual evaluations in "
             << std::fixed << std::setprecision(0) << p.seconds
             << " s, largest net force " << std::scientific
             << std::setprecision(2) << p.largest_force << " N, balanced below "
             << p.balanced_below << " N";
        *out << line.str() << std::endl;
      };
    stepper->report_relaxations(report, relaxation_report_interval);
  }

  LoadStepResult
  DieCompaction::advance(Bed &bed, const DieWalls &target)
  {
    return elastic ? elastic->advance(bed, target)
                   : stepper->advance(bed, target);
  }

  void
  DieCompaction::set_output(std::ostream *csv_, std::ostream *progress_)
  {
    csv      = csv_;
    progress = progress_;
    report_relaxations();
  }

  void
  DieCompaction::check(const LoadStepResult &r, const std::string &what)
  {
    work += r.work;

    if (!r.converged)
      {
        std::ostringstream s;
        s << "die protocol: equilibrium failed during " << what
          << " (relative residual " << r.last.relative_residual << " after "
          << r.cutbacks << " cut-backs); the last converged state is kept";
        failure_message = s.str();
        if (progress)
          *progress << failure_message << std::endl;
        throw std::runtime_error(failure_message);
      }
  }

  DieRecord
  DieCompaction::record(const Bed            &bed,
                        const std::string    &stage,
                        const int             branch,
                        const int             step,
                        const LoadStepResult &r)
  {
    DieRecord d;
    d.stage                = stage;
    d.branch               = branch;
    d.step                 = step;
    d.punch_gap            = bed.walls.height();
    d.relative_density     = bed.relative_density();
    const auto &s          = r.last.sums;
    d.upper_punch_force    = s.wall_force[int(Wall::upper_punch)];
    d.lower_punch_force    = s.wall_force[int(Wall::lower_punch)];
    d.die_wall_force       = s.wall_force[int(Wall::die)];
    d.upper_punch_pressure = d.upper_punch_force / bed.walls.punch_area();
    d.lower_punch_pressure = d.lower_punch_force / bed.walls.punch_area();
    d.die_wall_pressure
      = bed.walls.die_present ? d.die_wall_force / bed.walls.wall_area() : 0.0;
    if (elastic)
      {
        // No bonds; bed.contacts holds no state of the elastic law.
        Bed copy              = bed;
        d.coordination_number = elastic->coordination(copy);
      }
    else
      {
        const BedMeasures m   = measure(bed, force_resolution());
        d.coordination_number = m.coordination_number;
        d.bonding_surface     = m.bonding_surface;
        d.bonds               = m.n_bonds;
      }
    const double           diameter = 2.0 * bed.particles.mean_radius();
    const InteriorMeasures interior
      = measure_interior(bed,
                         protocol.interior_wall_distance * diameter,
                         elastic ? 0.0 : force_resolution(),
                         protocol.interior_min_extent * diameter);
    d.rho_interior          = interior.relative_density;
    d.sigma_zz_interior     = interior.sigma_zz;
    d.sigma_rr_interior     = interior.sigma_rr;
    d.coordination_interior = interior.coordination_number;
    d.bonds_formed          = r.bonds.formed;
    d.bonds_broken          = r.bonds.broken;
    d.residual              = r.last.relative_residual;
    d.mean_contact_force    = s.mean_force;
    d.iterations            = r.work.iterations;
    d.cg_iterations         = r.work.cg_iterations;
    d.cutbacks              = r.cutbacks;
    d.relaxed               = r.relaxed ? 1 : 0;
    d.wall_seconds          = now() - start_time;
    return d;
  }

  void
  DieCompaction::emit(const DieRecord &r, const Bed &state)
  {
    rows.push_back(r);
    last_good = state;
    if (csv)
      {
        write_csv_row(*csv, r);
        csv->flush();
      }
    if (on_record)
      on_record(r);
  }

  void
  DieCompaction::run()
  {
    const FormatGuard keep_format(progress);
    start_time = now();
    if (csv)
      write_csv_header(*csv);
    // The filled bed is force-free up to round-off (touching spheres, no
    // gravity): record it as is.
    LoadStepResult initial;
    initial.converged = true;
    if (elastic)
      initial.last.sums = elastic->sums(path);
    else
      {
        ContactAssembler a;
        Eigen::VectorXd  F;
        initial.last.sums = a.residual(path, model, F);
      }
    DieRecord r0      = record(path, "compaction", 0, 0, initial);
    r0.rho_max_in_die = r0.relative_density;
    emit(r0, path);
    failure_message.clear();
    completed     = 0;
    n_branches    = 0;
    stopped_early = false;
    // Elastic spheres carry no history: relaxing them to jamming is their
    // quasi-static path, not a shortcut.
    if (protocol.consolidate || elastic)
      consolidate();

    compact_from(0);
  }

  void
  DieCompaction::compact_from(const std::size_t first)
  {
    const auto &targets = protocol.compaction_targets;
    for (std::size_t k = first; k < targets.size(); ++k)
      {
        if (targets[k] <= path.relative_density() * (1 + 1e-12))
          {
            for (const double u : protocol.unloading_points)
              if (std::abs(u - targets[k]) < 1e-12 && progress)
                *progress << "unloading point " << u
                          << " lies below the jamming density "
                          << path.relative_density() << ": skipped"
                          << std::endl;
          }
        else
          {
            compact_to(targets[k],
                       static_cast<int>(k + 1),
                       static_cast<int>(targets.size()));
            for (const double u : protocol.unloading_points)
              if (std::abs(u - targets[k]) < 1e-12)
                unloading_branch(++n_branches);
          }
        completed       = k + 1;
        const bool last = completed == targets.size();
        const bool stop = !last && protocol.stop_after > 0
                          && completed >= std::size_t(protocol.stop_after);
        const bool due = protocol.checkpoint_interval > 0
                         && completed % protocol.checkpoint_interval == 0;
        if (!last && (due || stop))
          {
            if (on_checkpoint)
              on_checkpoint(path, progress_state());
            // The next step starts as a resumed run does: no secant
            // predictor, no cut-back memory.
            reset_stepper();
            if (progress)
              *progress << "checkpoint after " << completed << " of "
                        << targets.size() << " compaction targets" << std::endl;
          }
        if (stop)
          {
            stopped_early = true;
            if (progress)
              *progress << "stopping after " << completed
                        << " compaction targets as asked" << std::endl;
            return;
          }
      }
  }

  DieProgress
  DieCompaction::progress_state() const
  {
    DieProgress p;
    p.compaction_targets = protocol.compaction_targets;
    p.completed_targets  = completed;
    p.branches_run       = n_branches;
    p.jamming_density    = rho_jammed;
    p.rows               = rows;
    p.branches           = summaries;
    p.work               = work;
    return p;
  }

  std::string
  DieCompaction::resume_mismatch(const DieProgress &from) const
  {
    const auto &targets = protocol.compaction_targets;
    if (from.completed_targets > from.compaction_targets.size()
        || from.completed_targets > targets.size())
      return "the checkpoint has more completed compaction targets than "
             "this run has";
    if (from.rows.empty())
      return "the checkpoint has no rows";
    for (std::size_t k = 0; k < from.completed_targets; ++k)
      if (std::abs(targets[k] - from.compaction_targets[k])
          > 1e-12 * targets[k])
        {
          std::ostringstream s;
          s << "compaction target " << k + 1 << " is " << std::setprecision(12)
            << targets[k] << " here but was " << from.compaction_targets[k]
            << " in the checkpointed run (same packing, final density, "
               "compaction steps and unloading points up to the checkpoint "
               "are needed)";
          return s.str();
        }
    return {};
  }

  void
  DieCompaction::resume(const DieProgress &from)
  {
    const FormatGuard keep_format(progress);
    const auto       &targets  = protocol.compaction_targets;
    const std::string mismatch = resume_mismatch(from);
    if (!mismatch.empty())
      throw std::invalid_argument("die protocol: " + mismatch);
    failure_message.clear();
    rows       = from.rows;
    summaries  = from.branches;
    completed  = from.completed_targets;
    n_branches = from.branches_run;
    rho_jammed = from.jamming_density;
    work       = from.work;
    last_good  = path;
    start_time = now() - (rows.empty() ? 0.0 : rows.back().wall_seconds);
    if (csv)
      {
        write_csv_header(*csv);
        for (const auto &r : rows)
          write_csv_row(*csv, r);
        csv->flush();
      }
    if (progress)
      *progress << "resuming after " << completed << " of " << targets.size()
                << " compaction targets (in-die relative density "
                << path.relative_density() << ", " << n_branches
                << " unloading branches done)" << std::endl;
    compact_from(completed);
  }

  void
  DieCompaction::rerun_branch(const int branch)
  {
    const FormatGuard keep_format(progress);
    start_time = now();
    if (csv)
      write_csv_header(*csv);
    failure_message.clear();
    const LoadStepResult r
      = elastic ? elastic->equilibrate(path) : stepper->equilibrate(path);
    check(r, "re-equilibrating the saved compaction state");
    DieRecord d      = record(path, "compaction", 0, 0, r);
    d.rho_max_in_die = d.relative_density;
    emit(d, path);
    unloading_branch(branch);
  }

  void
  DieCompaction::consolidate()
  {
    const auto &targets = protocol.compaction_targets;
    if (targets.empty())
      return;
    Consolidation             c(protocol.consolidation);
    const ConsolidationResult r
      = elastic
          ? elastic->consolidate(path, targets.back(), protocol.consolidation)
          : c.run(path, model, targets.back());
    work.fire_seconds += r.seconds;
    work.fire_iterations += r.iterations;
    work.assemblies += r.assemblies;
    rho_jammed = r.jammed ? path.relative_density() : 0.0;
    if (progress)
      *progress << "consolidation: " << (r.jammed ? "jammed" : "not jammed")
                << " at rho " << std::setprecision(4) << path.relative_density()
                << ", punch "
                << r.sums.wall_force[int(Wall::upper_punch)]
                     / path.walls.punch_area() / 1e6
                << " MPa, " << r.increments << " increments, " << r.iterations
                << " relaxation iterations, " << std::setprecision(3)
                << r.seconds << " s" << std::defaultfloat << std::endl;
    if (r.failed)
      {
        failure_message = "die protocol: consolidation failed to relax the "
                          "bed; the last relaxed state is kept";
        last_good       = path;
        throw std::runtime_error(failure_message);
      }
  }

  void
  DieCompaction::compact_to(const double rho, const int step, const int n_steps)
  {
    DieWalls target         = path.walls;
    target.upper_punch      = path.walls.lower_punch + gap_for(path, rho);
    const double         t0 = now();
    const LoadStepResult r  = advance(path, target);
    std::ostringstream   what;
    what << "compaction to relative density " << rho;
    check(r, what.str());
    DieRecord d      = record(path, "compaction", 0, step, r);
    d.rho_max_in_die = d.relative_density;
    // The bonded path jams where the punches first carry the jamming
    // pressure (from there on Newton solves every step); the other
    // protocols have no onset of their own to find.
    const bool bonded_path = !protocol.consolidate && !elastic;
    if (bonded_path && rho_jammed == 0.0 && !stepper->unjammed(path))
      rho_jammed = d.relative_density;
    emit(d, path);
    if (progress)
      {
        // Before jamming the cost of the onset ahead is unknown: the mean
        // so far (cheap loose steps) only bounds what is left from below.
        // The bonded path is loose until rho_jammed is set, just above.
        const bool   loose = bonded_path && rho_jammed == 0.0;
        const double left  = compaction_seconds_left(
          rows, rho_jammed, step, n_steps, now() - start_time);
        *progress << "compaction " << std::setw(3) << step << "/" << n_steps
                  << "  rho " << std::fixed << std::setprecision(4)
                  << d.relative_density << "  punch " << std::setprecision(2)
                  << d.upper_punch_pressure / 1e6 << " MPa  Z "
                  << d.coordination_number << "  it " << r.work.iterations
                  << " (cg " << r.work.cg_iterations << ", relax "
                  << r.work.fire_iterations << ", cut " << r.cutbacks << ")  "
                  << std::setprecision(1) << now() - t0 << " s  left "
                  << (loose ? "> " : "~") << left << " s"
                  << (loose ? " (loose bed, jamming onset ahead)" : "")
                  << std::defaultfloat << std::endl;
      }
  }

  void
  DieCompaction::unloading_branch(const int branch)
  {
    // The branch steps with a fresh stepper of its own, as a run resumed
    // from the branch's checkpoint does: the memory of its unloading and
    // ejection (secant predictor, sub-step, trust radius) does not carry
    // into the next compaction step, so the compaction path does not depend
    // on the branches taken.
    auto compaction_stepper = std::move(stepper);
    auto compaction_elastic = std::move(elastic);
    reset_stepper();

    Bed bed = path; // the saved state of the compaction path
    if (on_branch_state)
      on_branch_state(bed, "compaction", branch);
    BranchSummary s;
    s.branch                    = branch;
    s.rho_max_in_die            = bed.relative_density();
    const double H_max          = bed.walls.height();
    s.max_punch_pressure        = rows.back().upper_punch_pressure;
    s.coordination_compacted    = rows.back().coordination_number;
    s.bonding_surface_compacted = rows.back().bonding_surface;

    std::vector<double> strain{0.0}, axial{rows.back().upper_punch_pressure},
      radial{rows.back().die_wall_pressure};
    double    F_prev = rows.back().upper_punch_force, H_prev = H_max;
    double    H_min = H_max;
    DieRecord last;
    double    dH = protocol.unloading_step * H_max;
    for (int step = 1;; ++step)
      {
        DieWalls w = bed.walls;
        w.upper_punch += dH;
        const LoadStepResult r = advance(bed, w);
        check(r, "unloading");
        DieRecord d      = record(bed, "unloading", branch, step, r);
        d.rho_max_in_die = s.rho_max_in_die;
        const double H   = bed.walls.height();
        strain.push_back((H - H_max) / H_max);
        axial.push_back(d.upper_punch_pressure);
        radial.push_back(d.die_wall_pressure);
        if (d.upper_punch_force <= force_resolution() || step > 10000)
          {
            // The punch separated within this step: its force vanished or
            // fell below the force resolution, the force Z and Eq. (13)
            // read as none (a balanced state can leave the punch a
            // round-off force). The secant through this state and the one
            // before gives the gap at which the force vanished.
            const double F = d.upper_punch_force;
            H_min
              = F_prev > F ? H_prev + (H - H_prev) * F_prev / (F_prev - F) : H;
            s.rho_min_in_die
              = bed.particles.solid_volume() / (bed.walls.punch_area() * H_min);
            s.elastic_recovery_rho
              = (s.rho_max_in_die - s.rho_min_in_die) / s.rho_max_in_die;
            s.elastic_recovery_H = (H_min - H_max) / H_max;
            s.residual_radial_pressure
              = d.die_wall_force / (pi * bed.walls.diameter * H_min);
            s.bonding_surface_unloaded = d.bonding_surface;
            d.rho_min_in_die           = s.rho_min_in_die;
            d.elastic_recovery_rho     = s.elastic_recovery_rho;
            d.elastic_recovery_H       = s.elastic_recovery_H;
            d.residual_radial_pressure = s.residual_radial_pressure;
            emit(d, bed);
            last = d;
            break;
          }
        emit(d, bed);
        if (progress && protocol.verbose)
          *progress << "  unloading step " << step << " F "
                    << d.upper_punch_force << " it " << r.work.iterations
                    << " cg " << r.work.cg_iterations << " fire "
                    << r.work.fire_iterations << std::endl;
        if (step == 1 && F_prev > d.upper_punch_force
            && protocol.min_unloading_steps > 1)
          {
            // Secant stiffness of the first step: the force vanishes about
            // F / k further on.
            const double k = (F_prev - d.upper_punch_force) / (H - H_prev);
            dH = std::min(dH, F_prev / k / protocol.min_unloading_steps);
          }
        F_prev = d.upper_punch_force;
        H_prev = H;
      }
    s.tablet = unloading_elasticity(strain, axial, radial);
    // The compact's envelope at C, where its volume is known (punch gap
    // H_min times the die cross-section).
    const auto [n_theta, n_z] = envelope_sectors(bed);
    const double envelope     = envelope_volume(bed, n_theta, n_z);
    if (progress)
      *progress << std::setprecision(4) << "unloading branch " << branch
                << ": rho_max " << s.rho_max_in_die << "  rho_min "
                << s.rho_min_in_die << "  recovery "
                << 100 * s.elastic_recovery_rho << " %  residual radial "
                << s.residual_radial_pressure / 1e6 << " MPa" << std::endl;
    if (on_branch_state)
      on_branch_state(bed, "unloading", branch);
    if (protocol.eject)
      {
        eject(bed, branch, s, envelope, {n_theta, n_z});
        if (on_branch_state)
          on_branch_state(bed, "ejection", branch);
      }
    summaries.push_back(s);
    stepper = std::move(compaction_stepper);
    elastic = std::move(compaction_elastic);
  }

  void
  DieCompaction::eject(Bed                      &bed,
                       const int                 branch,
                       BranchSummary            &s,
                       const double              envelope_in_die,
                       const std::pair<int, int> sectors)
  {
    // Out of the die the compact is free radially: its volume is the in-die
    // volume at C scaled by the change of its envelope volume (same
    // definition before and after, so surface roughness cancels).
    auto tablet_density = [&](const Bed &b) {
      return s.rho_min_in_die * envelope_in_die
             / envelope_volume(b, sectors.first, sectors.second);
    };
    // The upper punch stays where it stopped carrying force (so that loose
    // surface particles are not lost); the die wall then opens in steps.
    // Ejection pressure (Sec. 5.4): mu times the radial wall force over
    // the punch area, largest at the start of ejection.
    const double area   = bed.walls.punch_area();
    const double F_die  = rows.back().die_wall_force;
    s.ejection_pressure = protocol.friction_coefficient * F_die / area;
    const double D0     = bed.walls.diameter;
    DieWalls     w      = bed.walls;
    for (int step = 1; step <= protocol.max_ejection_steps + 1; ++step)
      {
        const bool remove = step > protocol.max_ejection_steps;
        if (remove)
          w.die_present = false;
        else
          w.diameter = D0 * (1.0 + protocol.ejection_step * step);
        const LoadStepResult r = advance(bed, w);
        check(r, "ejection");
        DieRecord d                = record(bed, "ejection", branch, step, r);
        d.rho_max_in_die           = s.rho_max_in_die;
        d.rho_min_in_die           = s.rho_min_in_die;
        d.elastic_recovery_rho     = s.elastic_recovery_rho;
        d.elastic_recovery_H       = s.elastic_recovery_H;
        d.residual_radial_pressure = s.residual_radial_pressure;
        d.ejection_pressure
          = protocol.friction_coefficient * d.die_wall_force / area;
        d.rho_tablet = tablet_density(bed);
        emit(d, bed);
        if (progress && protocol.verbose)
          *progress << "  ejection step " << step << " F_die "
                    << d.die_wall_force << " it " << r.work.iterations << " cg "
                    << r.work.cg_iterations << " fire "
                    << r.work.fire_iterations << std::endl;
        if (d.die_wall_force == 0.0 && !remove)
          {
            // The tablet left the wall: remove it.
            w.die_present           = false;
            const LoadStepResult rf = advance(bed, w);
            check(rf, "ejection");
            DieRecord f      = record(bed, "ejection", branch, step + 1, rf);
            f.rho_max_in_die = s.rho_max_in_die;
            f.rho_min_in_die = s.rho_min_in_die;
            f.rho_tablet     = tablet_density(bed);
            emit(f, bed);
            break;
          }
        if (remove)
          break;
      }
    s.rho_tablet              = rows.back().rho_tablet;
    s.bonding_surface_ejected = rows.back().bonding_surface;
    if (progress)
      *progress << std::setprecision(4) << "ejection branch " << branch
                << ": ejection pressure " << s.ejection_pressure / 1e6
                << " MPa (mu " << protocol.friction_coefficient
                << ")  rho_tablet " << s.rho_tablet << std::endl;
  }

  void
  DieCompaction::write_csv_header(std::ostream &out)
  {
    out << "stage,branch,step,punch_gap,relative_density,rho_max_in_die,"
           "rho_min_in_die,rho_tablet,upper_punch_force,lower_punch_force,"
           "die_wall_force,upper_punch_pressure,lower_punch_pressure,"
           "die_wall_pressure,coordination_number,bonding_surface,bonds,"
           "bonds_formed,bonds_broken,elastic_recovery_rho,"
           "elastic_recovery_H,residual_radial_pressure,ejection_pressure,"
           "residual,iterations,cg_iterations,cutbacks,relaxed,rho_interior,"
           "sigma_zz_interior,sigma_rr_interior,coordination_interior\n";
  }

  void
  DieCompaction::write_csv_row(std::ostream &out, const DieRecord &r)
  {
    const auto old = out.precision(10);
    out << r.stage << ',' << r.branch << ',' << r.step << ',' << r.punch_gap
        << ',' << r.relative_density << ',' << r.rho_max_in_die << ','
        << r.rho_min_in_die << ',' << r.rho_tablet << ',' << r.upper_punch_force
        << ',' << r.lower_punch_force << ',' << r.die_wall_force << ','
        << r.upper_punch_pressure << ',' << r.lower_punch_pressure << ','
        << r.die_wall_pressure << ',' << r.coordination_number << ','
        << r.bonding_surface << ',' << r.bonds << ',' << r.bonds_formed << ','
        << r.bonds_broken << ',' << r.elastic_recovery_rho << ','
        << r.elastic_recovery_H << ',' << r.residual_radial_pressure << ','
        << r.ejection_pressure << ',' << r.residual << ',' << r.iterations
        << ',' << r.cg_iterations << ',' << r.cutbacks << ',' << r.relaxed
        << ',' << r.rho_interior << ',' << r.sigma_zz_interior << ','
        << r.sigma_rr_interior << ',' << r.coordination_interior << '\n';
    out.precision(old);
  }
} // namespace compax::dem

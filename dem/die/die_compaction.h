#pragma once

#include "dem/die/die_analysis.h"
#include "dem/die/die_interior.h"
#include "dem/nonlocal/elastic_die_stepper.h"
#include "dem/solver/consolidation.h"
#include "dem/solver/load_stepper.h"
#include "dem/solver/solver_work.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace compax::dem
{
  /// Parameters of the die protocol of Gonzalez 2018, Sec. 5.
  struct DieProtocol
  {
    /// In-die relative densities the compaction passes through, in
    /// increasing order (one load step each) [-].
    std::vector<double> compaction_targets;
    /// rho_max^in-die at which an unloading branch starts [-]; each is
    /// added to the compaction targets.
    std::vector<double> unloading_points;
    /// Upper-punch withdrawal per unloading step as a fraction of the
    /// punch gap at the unloading point [-].
    double unloading_step = 2e-3;
    /// Smallest number of unloading steps aimed at per branch, so that the
    /// central third of the unloading curve has points for the tablet's E
    /// and nu (Sec. 5.7): after the first step, the step is reduced to the
    /// gap at which the punch force would vanish, extrapolated with that
    /// step's secant stiffness, divided by this number.
    int min_unloading_steps = 12;
    /// Die-wall friction coefficient mu of the ejection pressure [-].
    double friction_coefficient = 1.0;
    /// Die-radius increase per ejection step as a fraction of D/2 [-].
    double ejection_step = 2e-4;
    /// Ejection steps before the die wall is removed altogether.
    int max_ejection_steps = 40;
    /// Whether to eject after each unloading branch.
    bool eject = true;
    /**
     * How the loose deposit reaches jamming.
     * - false (the bonded path, default): every compaction target is a
     *   load step from the deposit on, and Eq. (13) is applied at every
     *   converged state (Gonzalez 2018, Algorithm 1): bridges form from
     *   the first resolved contact force on. Below
     *   consolidation.jamming_pressure on the punches a step is balanced
     *   at fixed internal variables by the minimiser unjammed_equilibrium
     *   selects (Newton has no stiffness along the mechanisms of an
     *   unjammed bed), and that balanced state is the converged state the
     *   history update applies to; above it the
     *   trust-region Newton solves to EquilibriumOptions' tolerances.
     *   Contact forces below force_resolution() grow no plastic radius.
     * - true (frozen-history consolidation, the former default, kept for
     *   comparison): the punch advances in adaptive increments while the
     *   bed relaxes at fixed (virgin) internal variables, without plastic
     *   deformation or bridges, until the relaxed bed carries
     *   consolidation.jamming_pressure; only then do the load steps and
     *   Eq. (13) start. Compaction targets and unloading points below the
     *   density so reached are skipped.
     */
    bool                 consolidate = false;
    ConsolidationOptions consolidation;
    /// Bonded path: the converged state of an unjammed step
    /// (LoadSteppingOptions::unjammed_equilibrium).
    UnjammedEquilibrium unjammed_equilibrium
      = UnjammedEquilibrium::balanced_lbfgs;
    /// Bonded path: the predictor of an unjammed step is the secant one
    /// (true) or the affine one (false)
    /// (LoadSteppingOptions::secant_predictor_unjammed).
    bool secant_predictor_unjammed = true;
    /// Bonded path: where Newton fails on a sub-step that opens the punch
    /// gap, the balanced relaxation takes it at once instead of after the
    /// cut-backs (LoadSteppingOptions::relax_opening_at_first_failure).
    bool relax_opening_at_first_failure = true;
    /// Bonded path: true, a contact whose force is not above
    /// force_resolution() keeps its internal variables when Eq. (13) is
    /// applied (LoadSteppingOptions::resolved_history); false, Eq. (13)
    /// applies at every positive overlap of a converged state, however
    /// small its force.
    bool resolved_history = true;
    /// Elastic frictionless spheres instead of the ContactModel's bonded
    /// elasto-plastic law: Hertz, or the nonlocal contact formulation of
    /// Gonzalez & Cuitino 2012 (elastic->nonlocal), stepped by an
    /// ElasticDieStepper (consolidation by FIRE with Hertz contacts, then
    /// TrustRegionNewton with nonlocal_equilibrium_options()). No bonds:
    /// bonding surface and bonds are 0, the coordination number counts the
    /// loaded particle pairs. Empty: the ContactModel's law (LoadStepper,
    /// TrustRegionNewton).
    std::optional<ElasticDieOptions> elastic;
    /// The interior of the compact, whose stress and solid fraction die.csv
    /// reports beside the die averages (measure_interior(), each sphere
    /// weighted by its volume inside): the region farther than this many
    /// mean particle diameters from the die wall and both punches [-].
    double interior_wall_distance = 2.0;
    /// ... measured only while it is at least this many mean diameters
    /// high and wide (measure_interior()'s min_extent) [-].
    double interior_min_extent = 4.0;
    /// Also write a progress line per unloading and ejection step.
    bool verbose = false;
    /// Hand a checkpoint (DieCompaction::on_checkpoint) every this many
    /// compaction targets, after the target's unloading branch if it has
    /// one; 0: never.
    int checkpoint_interval = 0;
    /// Stop after this many compaction targets (with a checkpoint), e.g.
    /// to split a long study over several jobs; 0: run to the end.
    int stop_after = 0;
  };

  /// One row of die.csv: the state after a converged load step.
  struct DieRecord
  {
    std::string stage; // compaction, unloading, ejection
    int         branch                   = 0;
    int         step                     = 0;
    double      punch_gap                = 0.0;
    double      relative_density         = 0.0;
    double      rho_max_in_die           = 0.0;
    double      rho_min_in_die           = 0.0;
    double      rho_tablet               = 0.0;
    double      upper_punch_force        = 0.0;
    double      lower_punch_force        = 0.0;
    double      die_wall_force           = 0.0;
    double      upper_punch_pressure     = 0.0;
    double      lower_punch_pressure     = 0.0;
    double      die_wall_pressure        = 0.0;
    double      coordination_number      = 0.0;
    double      bonding_surface          = 0.0;
    std::size_t bonds                    = 0;
    std::size_t bonds_formed             = 0;
    std::size_t bonds_broken             = 0;
    double      elastic_recovery_rho     = 0.0;
    double      elastic_recovery_H       = 0.0;
    double      residual_radial_pressure = 0.0;
    double      ejection_pressure        = 0.0;
    double      residual                 = 0.0;
    /// Mean |P| over the loaded contacts [N] (the residual's scale; not
    /// written to die.csv).
    double mean_contact_force = 0.0;
    int    iterations         = 0;
    int    cg_iterations      = 0;
    int    cutbacks           = 0;
    /// 1: the state is an unjammed relaxation of the bonded path, balanced
    /// to ConsolidationOptions::relative_tolerance or the force resolution
    /// (DieCompaction::force_resolution()); 0: a Newton solution to the
    /// Solver tolerances (or a record without a solve).
    int relaxed = 0;
    /// Solid fraction and axial and radial Love-Weber stress (tension
    /// positive) of the interior (DieProtocol::interior_wall_distance,
    /// measure_interior()) [-], [Pa], [Pa]; NaN where it holds no particle.
    double rho_interior      = 0.0;
    double sigma_zz_interior = 0.0;
    double sigma_rr_interior = 0.0;
    /// Coordination number of the interior (InteriorMeasures) [-].
    double coordination_interior = 0.0;
    /// Wall time since the run (or its resumption) started [s]: not in
    /// die.csv (two runs of one study give the same file), the app writes
    /// it to timing.csv.
    double wall_seconds = 0.0;
  };

  /// The outcome of one unloading branch (and its ejection).
  struct BranchSummary
  {
    int    branch         = 0;
    double rho_max_in_die = 0.0, rho_min_in_die = 0.0, rho_tablet = 0.0;
    double max_punch_pressure        = 0.0;
    double elastic_recovery_rho      = 0.0;
    double elastic_recovery_H        = 0.0;
    double residual_radial_pressure  = 0.0;
    double ejection_pressure         = 0.0;
    double bonding_surface_compacted = 0.0;
    double bonding_surface_unloaded  = 0.0;
    double bonding_surface_ejected   = 0.0;
    double coordination_compacted    = 0.0;
    TabletElasticity tablet;
  };

  /**
   * Where a die protocol stands after a number of compaction targets: what
   * a checkpoint holds besides the bed on the compaction path, and what
   * DieCompaction::resume() continues from.
   */
  struct DieProgress
  {
    /// The compaction targets (unloading points merged in) of the run [-].
    std::vector<double> compaction_targets;
    /// How many of them are done (their branches included).
    std::size_t completed_targets = 0;
    /// Unloading branches run so far.
    int branches_run = 0;
    /// See DieCompaction::jamming_density() [-].
    double                     jamming_density = 0.0;
    std::vector<DieRecord>     rows;
    std::vector<BranchSummary> branches;
    /// Solver work so far (performance reports; a checkpoint keeps the
    /// counts, not the times).
    SolverWork work;
  };

  /**
   * Die compaction, unloading and ejection of a bed (Gonzalez 2018,
   * Sec. 5, Fig. 2): the upper punch moves down through the target
   * densities; at every unloading point the state is saved and an
   * unloading branch runs on a copy: the upper punch withdraws until it
   * carries no force (C in Fig. 2), then the die wall is removed in steps
   * (D). Each converged step is one row of die.csv.
   */
  class DieCompaction
  {
  public:
    /// equilibrium.force_floor = 0 is replaced by force_tolerance times the
    /// force of the jamming pressure on a mean particle's cross-section.
    DieCompaction(Bed                 bed,
                  const ContactModel &model,
                  DieProtocol         protocol,
                  EquilibriumOptions  equilibrium = {});

    /// Where rows go as they are computed (CSV with header); progress
    /// lines go to `progress` (may be null), among them a line every 30 s
    /// of a relaxation that runs that long (the jamming onset of a large
    /// bed: one load step may relax for minutes).
    void
    set_output(std::ostream *csv, std::ostream *progress);

    /// Called with every row as it is emitted (after the CSV got it).
    std::function<void(const DieRecord &row)> on_record;

    /**
     * Called with the three states of each branch that Gonzalez 2018 Sec.
     * 5.5 analyses (stage "compaction": the compaction path at the
     * unloading point; "unloading": the compact at C, the punch just free;
     * "ejection": the ejected tablet), for snapshots, fabric and force
     * histograms, and checkpoints. The bed must not be kept by reference.
     */
    std::function<void(const Bed &bed, const std::string &stage, int branch)>
      on_branch_state;

    /**
     * Called every protocol.checkpoint_interval compaction targets with
     * the bed on the compaction path and the progress so far: together
     * they are what resume() needs. The load stepper starts afresh after
     * each checkpoint (no secant predictor, full sub-step), so a run
     * resumed from it retraces the uninterrupted run exactly.
     */
    std::function<void(const Bed &bed, const DieProgress &progress)>
      on_checkpoint;

    /**
     * Runs the whole protocol. If a load step cannot converge after all
     * cut-backs, it throws std::runtime_error; failed(), failure() and
     * last_converged() then describe where it stopped, and records()
     * holds every converged row up to there.
     */
    void
    run();

    /**
     * Reruns one unloading branch (unloading and ejection) from the bed this
     * object was built with, a saved compaction state such as a
     * checkpoint: the state is re-equilibrated (it was converged when
     * saved, so nothing moves beyond the tolerance), recorded, then
     * unloaded and ejected exactly as run() does at that unloading point.
     */
    void
    rerun_branch(int branch);

    /**
     * Continues an interrupted run() from a checkpoint: the bed this object
     * was built with is the compaction path after
     * from.completed_targets targets; the rows and branches so far are
     * taken over (and written to the CSV first), then the remaining
     * targets run as run() would. The object's compaction targets must
     * begin with the completed ones of `from` (std::invalid_argument
     * otherwise); later ones may differ (e.g. a higher final density).
     */
    void
    resume(const DieProgress &from);

    /// Why resume(from) would refuse `from` (empty if it would not).
    std::string
    resume_mismatch(const DieProgress &from) const;

    /// The progress so far (what a checkpoint stores besides the bed).
    DieProgress
    progress_state() const;

    /// The compaction targets, unloading points merged in [-].
    const std::vector<double> &
    compaction_targets() const
    {
      return protocol.compaction_targets;
    }

    /// Whether run() or resume() stopped at protocol.stop_after.
    bool
    stopped() const
    {
      return stopped_early;
    }

    /// Whether run() stopped at a load step that did not converge.
    bool
    failed() const
    {
      return !failure_message.empty();
    }

    /// What failed (empty if nothing did).
    const std::string &
    failure() const
    {
      return failure_message;
    }

    /// The state of the last emitted row (compaction path, unloading or
    /// ejection branch): the state to write after a failure.
    const Bed &
    last_converged() const
    {
      return last_good;
    }

    /// Pressures below this are not resolved [Pa]: the punch pressure of
    /// the jammed states the fits of Eqs. (14)-(15) use exceeds it
    /// (consolidation.force_floor_fraction x jamming_pressure, 5 kPa by
    /// default).
    double
    pressure_resolution() const;

    /// Contact forces below this are not resolved [N]: the pressure
    /// resolution on a mean cross-section pi R^2. The coordination number
    /// counts the contacts above it, and Eq. (13) grows no plastic radius
    /// below it (bonded path).
    double
    force_resolution() const;

    /// In-die relative density at which the bed jammed [-]: where the
    /// frozen-history consolidation ended, or on the bonded path the first
    /// compaction state whose punches carried the jamming pressure (from
    /// there on Newton solves every step); 0 if not reached.
    double
    jamming_density() const
    {
      return rho_jammed;
    }

    const std::vector<DieRecord> &
    records() const
    {
      return rows;
    }

    const std::vector<BranchSummary> &
    branches() const
    {
      return summaries;
    }

    /// The bed on the compaction path.
    const Bed &
    bed() const
    {
      return path;
    }

    /// Header and one row of die.csv (no timing: see wall_seconds).
    static void
    write_csv_header(std::ostream &out);
    static void
    write_csv_row(std::ostream &out, const DieRecord &r);

    /// Totals for performance reports, the consolidation's relaxation
    /// included.
    SolverWork work;

  private:
    /// One load step with the law of the protocol.
    LoadStepResult
    advance(Bed &bed, const DieWalls &target);

    /// A fresh stepper (no predictor memory).
    void
    reset_stepper();

    /// Points the stepper's relaxation reports at `progress`.
    void
    report_relaxations();

    /// The compaction targets from index `first` on.
    void
    compact_from(std::size_t first);

    void
    compact_to(double rho, int step, int n_steps);

    void
    unloading_branch(int branch);

    void
    consolidate();

    void
    eject(Bed                &bed,
          int                 branch,
          BranchSummary      &summary,
          double              envelope,
          std::pair<int, int> sectors);

    DieRecord
    record(const Bed            &bed,
           const std::string    &stage,
           int                   branch,
           int                   step,
           const LoadStepResult &r);

    void
    emit(const DieRecord &r, const Bed &state);

    /// Adds the solver work of r to the totals (a failed step's cut-backs
    /// included), then throws when r did not converge.
    void
    check(const LoadStepResult &r, const std::string &what);

    Bed                                path;
    const ContactModel                &model;
    DieProtocol                        protocol;
    EquilibriumOptions                 equilibrium;
    std::unique_ptr<LoadStepper>       stepper;
    std::unique_ptr<ElasticDieStepper> elastic;
    std::vector<DieRecord>             rows;
    std::vector<BranchSummary>         summaries;
    std::ostream                      *csv        = nullptr;
    std::ostream                      *progress   = nullptr;
    double                             start_time = 0.0;
    Bed                                last_good;
    std::string                        failure_message;
    double                             rho_jammed    = 0.0;
    std::size_t                        completed     = 0;
    int                                n_branches    = 0;
    bool                               stopped_early = false;
  };
} // namespace compax::dem

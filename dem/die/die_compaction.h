#pragma once

#include "dem/die/die_analysis.h"
#include "dem/solver/consolidation.h"
#include "dem/solver/load_stepper.h"

#include <functional>
#include <iosfwd>
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
    /// Die-wall friction coefficient mu of the ejection pressure [-].
    double friction_coefficient = 1.0;
    /// Die-radius increase per ejection step as a fraction of D/2 [-].
    double ejection_step = 2e-4;
    /// Ejection steps before the die wall is removed altogether.
    int max_ejection_steps = 40;
    /// Whether to eject after each unloading branch.
    bool eject = true;
    /// Consolidate the loose deposit up to jamming before the static load
    /// steps (see Consolidation): the punch advances while the bed relaxes
    /// at fixed internal variables until the relaxed bed carries
    /// consolidation.jamming_pressure. Compaction targets and unloading
    /// points below the density so reached are skipped (no rows: the bed
    /// carries no force there).
    bool                 consolidate = true;
    ConsolidationOptions consolidation;
    /// Also write a progress line per unloading and ejection step.
    bool verbose = false;
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
    double wall_seconds       = 0.0;
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
    DieCompaction(Bed                 bed,
                  const ContactModel &model,
                  DieProtocol         protocol,
                  EquilibriumOptions  equilibrium = {});

    /// Where rows go as they are computed (CSV with header); progress
    /// lines go to `progress` (may be null).
    void
    set_output(std::ostream *csv, std::ostream *progress);

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

    /// In-die relative density at which consolidation found the bed jammed
    /// (0 without consolidation) [-].
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

    /// Header and one row of die.csv.
    static void
    write_csv_header(std::ostream &out);
    static void
    write_csv_row(std::ostream &out, const DieRecord &r);

    /// Totals for performance reports.
    double assembly_seconds = 0.0, linear_seconds = 0.0;
    double fire_seconds = 0.0;
    long   assemblies = 0, newton_iterations = 0, cg_iterations = 0,
         fire_iterations = 0;
    /// Consolidation: wall time and relaxation iterations.
    double consolidation_seconds    = 0.0;
    long   consolidation_iterations = 0;

  private:
    void
    compact_to(double rho, int step, int n_steps);

    void
    unloading_branch(int branch);

    void
    consolidate();

    void
    eject(Bed &bed, int branch, BranchSummary &summary, double envelope);

    DieRecord
    record(const Bed            &bed,
           const std::string    &stage,
           int                   branch,
           int                   step,
           const LoadStepResult &r);

    void
    emit(const DieRecord &r, const Bed &state);

    void
    check(const LoadStepResult &r, const std::string &what);

    Bed                        path;
    const ContactModel        &model;
    DieProtocol                protocol;
    LoadStepper                stepper;
    std::vector<DieRecord>     rows;
    std::vector<BranchSummary> summaries;
    std::ostream              *csv        = nullptr;
    std::ostream              *progress   = nullptr;
    double                     start_time = 0.0;
    Bed                        last_good;
    std::string                failure_message;
    double                     rho_jammed = 0.0;
  };
} // namespace compax::dem

#pragma once

#include "dem/die/die_compaction.h"
#include "dem/die/die_study_fits.h"
#include "dem/packing/ballistic_deposition.h"
#include "dem/solver/contact_model.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace compax::dem
{
  /// What a die study does: the bed it deposits, the protocol of Gonzalez
  /// 2018 Sec. 5 and the solver.
  struct DieStudyOptions
  {
    DepositionParameters deposition;
    /// Its compaction targets are set by the study (die_compaction_targets()
    /// from the starting bed to final_density); unloading points, steps,
    /// checkpoints and stop_after are used as given.
    DieProtocol        protocol;
    EquilibriumOptions equilibrium;
    /// In-die relative density at which compaction stops [-].
    double final_density = 0.87;
    /// Number of equal density steps from the starting bed to final_density.
    int compaction_steps = 20;
  };

  /// The final density does not exceed the starting bed's density: there is
  /// nothing to compact.
  class DieTargetError : public std::invalid_argument
  {
  public:
    DieTargetError(double final_density, double packing_density);

    /// In-die relative density of the starting bed [-].
    double packing_density;
  };

  /// The compaction targets from the packing's in-die relative density
  /// @p rho_0 (excluded) to @p final_density (included) in @p steps equal
  /// steps; throws DieTargetError unless final_density exceeds rho_0.
  std::vector<double>
  die_compaction_targets(double rho_0, double final_density, int steps);

  /**
   * Where a die study starts: a fresh deposit, the compaction state of an
   * interrupted run with its progress (a compaction checkpoint), or the
   * saved compaction state of one unloading branch to rerun (a branch
   * checkpoint).
   */
  struct DieStudyStart
  {
    /// The starting bed; empty: deposit DieStudyOptions::deposition.
    std::optional<Bed> bed;
    /// With bed: continue the run this progress describes.
    std::optional<DieProgress> progress;
    /// With bed: rerun this unloading branch (unloading and ejection) from
    /// it instead of the study; 0: no.
    int rerun_branch = 0;

    static DieStudyStart
    deposit();
    static DieStudyStart
    resume(Bed bed, DieProgress progress);
    static DieStudyStart
    branch(Bed bed, int branch);
  };

  /**
   * Progress reports of a run (each may be empty). An exception of type
   * std::runtime_error thrown by one ends the run as a failed step (the
   * result then says why).
   */
  struct DieStudyObserver
  {
    /// One line of progress text (no newline): deposition, compaction
    /// steps, branches, checkpoints.
    std::function<void(const std::string &line)> progress;
    /// Every converged state, as it is computed: one row of die.csv.
    std::function<void(const DieRecord &row)> row;
    /// The three analysed states of each branch
    /// (DieCompaction::on_branch_state).
    std::function<void(const Bed &bed, const std::string &stage, int branch)>
      branch_state;
    /// What resume needs, every protocol.checkpoint_interval compaction
    /// targets (DieCompaction::on_checkpoint) and, with an interval, once
    /// more at the end of a complete study: the output of a resumed run is
    /// that of the uninterrupted one.
    std::function<void(const Bed &bed, const DieProgress &progress)> checkpoint;
  };

  /// What a die study computed.
  struct DieStudyResult
  {
    /// Every converged state: the rows of die.csv, those taken over from a
    /// resumed run's progress first.
    std::vector<DieRecord> rows;
    /// How many of the rows were taken over (their wall time is not this
    /// run's).
    std::size_t taken_over = 0;
    /// One per unloading branch: the rows of branches.csv.
    std::vector<BranchSummary> branches;
    /// Eqs. (14)-(24) fitted to rows and branches.
    DieStudyFits fits;
    /// DieCompaction::pressure_resolution() [Pa].
    double pressure_resolution = 0.0;
    /// DieCompaction::jamming_density() [-].
    double jamming_density = 0.0;
    /// False if a step did not converge (or an observer threw): `failure`
    /// says why and `last_converged` holds the state of the last row.
    bool               converged = true;
    std::string        failure;
    std::optional<Bed> last_converged;
    /// Stopped after protocol.stop_after compaction targets.
    bool stopped = false;
    /// The run's solver work (performance reports).
    SolverWork solver;
  };

  /**
   * The die study of Gonzalez 2018 Sec. 5: a bed deposited in a rigid die
   * (or taken from a checkpoint) is compacted through the target
   * densities, unloaded at every unloading point and ejected
   * (DieCompaction); Eqs. (14)-(24) are fitted to the result. The library
   * form of `compax die`: progress, rows, analysed states and checkpoints
   * go to a DieStudyObserver, never to a stream or a file.
   */
  class DieStudy
  {
  public:
    /// Sets the compaction targets of a resumed start from the density of
    /// its first row, the deposit (throws DieTargetError if the final
    /// density is not above it); a fresh deposit gets them in run().
    DieStudy(ContactModel    model,
             DieStudyOptions options,
             DieStudyStart   start = DieStudyStart::deposit());

    /// Why a resumed start cannot continue its progress (other compaction
    /// targets up to the checkpoint); empty if it can.
    std::string
    resume_mismatch() const;

    /// Runs the study (once). Throws DieTargetError if a fresh deposit is
    /// as dense as the final density, std::invalid_argument if
    /// resume_mismatch() is not empty.
    DieStudyResult
    run(const DieStudyObserver &observer = {});

    const ContactModel &
    model() const
    {
      return model_;
    }

    const DieStudyOptions &
    options() const
    {
      return options_;
    }

  private:
    ContactModel    model_;
    DieStudyOptions options_;
    DieStudyStart   start_;
  };
} // namespace compax::dem

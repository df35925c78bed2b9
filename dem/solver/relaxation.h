#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/equilibrium_system.h"
#include "dem/solver/residual_norms.h"

#include <Eigen/Core>

#include <chrono>
#include <functional>

namespace compax::dem
{
  /// Where a running relaxation stands: what a progress report shows while
  /// one load step of a large bed relaxes for minutes (the jamming onset).
  struct RelaxationProgress
  {
    /// Residual evaluations so far (FIRE iterations, L-BFGS evaluations).
    int evaluations = 0;
    /// Wall time since the relaxation started [s].
    double seconds = 0.0;
    /// max_i |F_i| [N].
    double largest_force = 0.0;
    /// The force max_i |F_i| must fall below [N] (RelaxationBalance).
    double balanced_below = 0.0;
  };

  /// Receives RelaxationProgress while a relaxation runs.
  using RelaxationReport = std::function<void(const RelaxationProgress &)>;

  /// Outcome of a relaxation (FIRE or L-BFGS).
  struct FireResult
  {
    bool        converged         = false;
    int         iterations        = 0;
    double      relative_residual = 0.0;
    ContactSums sums;
    /// Residual evaluations with the stiffness (mass updates).
    int assemblies = 0;
    /// Stopped unconverged because it no longer approached balance
    /// (Relaxation::give_up_when_stalled).
    bool stalled = false;

    /// Where the relaxation stands after @p evaluations residual
    /// evaluations, by the shared stopping test (relaxation_balance).
    void
    record(const RelaxationBalance &balance, const int evaluations)
    {
      relative_residual = balance.relative_residual;
      converged         = balance.balanced;
      iterations        = evaluations;
    }
  };

  /**
   * A minimiser of a bed's stored energy at fixed walls and internal
   * variables, driven by forces only: the solver of the states where Newton
   * cannot go (a loose bed's mechanisms, a stalled Newton iteration). FIRE
   * and L-BFGS solve this one problem to one stopping rule, so the
   * protocols choose between them through this interface.
   */
  class Relaxation
  {
  public:
    virtual ~Relaxation() = default;

    /**
     * Relaxes until max_i |F_i| <= target_relative_residual times the mean
     * contact force, or max_i |F_i| <= force_floor [N] (forces negligible
     * in absolute terms), or until @p budget iterations (FIRE) or residual
     * evaluations (L-BFGS).
     */
    virtual FireResult
    relax(EquilibriumSystem &system,
          double             target_relative_residual,
          int                budget,
          double             force_floor = 0.0)
      = 0;

    /// The same for a die bed.
    FireResult
    relax(Bed                &bed,
          const ContactModel &model,
          double              target_relative_residual,
          int                 budget,
          double              force_floor = 0.0);

    /// Calls @p report every @p interval seconds [s] of wall time while a
    /// relaxation runs; an empty report (the default) reports nothing.
    /// Reading the clock costs nothing next to a residual evaluation.
    void
    report_progress(RelaxationReport report, double interval);

    /**
     * Makes relax() stop, unconverged, once @p window residual evaluations
     * (FIRE iterations) pass without halving the distance to balance,
     * max_i |F_i| over the force it must fall below; 0 (the default):
     * only the budget stops it. Near the jamming onset a relaxation
     * approaches balance steadily but slowly, for longer than any fixed
     * budget fits; one that stalls should give up long before it.
     */
    void
    give_up_when_stalled(int window);

  protected:
    /// Starts the clock of the reports and the stall test (at the start of
    /// relax()).
    void
    start_watching();

    /// result.record(balance, evaluations), the stall test, and a report
    /// if one is due.
    void
    record(FireResult              &result,
           const RelaxationBalance &balance,
           int                      evaluations);

    /// Assembles the residual into @p F and the stiffness at the system's
    /// state, and returns each coordinate's inverse diagonal stiffness in
    /// @p inverse_diagonal: the inverse masses of FIRE and the
    /// preconditioner of L-BFGS.
    void
    assemble_inverse_diagonal(EquilibriumSystem &system,
                              Eigen::VectorXd   &F,
                              Eigen::VectorXd   &inverse_diagonal);

    ContactAssembler  assembler;
    BlockSparseMatrix K;
    ContactSums       sums;

  private:
    RelaxationReport                      report;
    double                                report_interval = 0.0;
    std::chrono::steady_clock::time_point started, last_report;
    /// give_up_when_stalled()'s window [evaluations]; 0: off.
    int stall_window = 0;
    /// The distance to balance when it last halved, and when.
    double stall_reference    = 0.0;
    int    stall_reference_at = 0;
  };
} // namespace compax::dem

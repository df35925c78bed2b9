#pragma once

#include "fem/tablet_solver.h"

#include <functional>
#include <string>

namespace compax::fem
{
  /// The punch motions of one tableting cycle.
  struct TabletProcess
  {
    /// Upper punch travel into the die during compaction [m].
    double compaction_displacement = 3.11e-3;
    /// Upper punch withdrawal during unloading [m].
    double unloading_displacement = 0.3e-3;
    /// Lower punch travel during ejection [m] (to beyond the die top).
    double       ejection_displacement = 7.2e-3;
    unsigned int compaction_steps      = 240;
    unsigned int unloading_steps       = 40;
    unsigned int ejection_steps        = 40;
    /// Punch speed that turns travel into time [m/s].
    double punch_speed = 0.05;
  };

  enum class TabletStage
  {
    compaction,
    unloading,
    ejection
  };

  /// "compaction", "unloading" or "ejection".
  std::string
  stage_name(TabletStage stage);

  /// The state after one converged step of the cycle.
  struct TabletStep
  {
    unsigned int index = 0;
    /// Punch travel so far / punch speed [s].
    double      time  = 0.0;
    TabletStage stage = TabletStage::compaction;
    /// Upper punch displacement from its initial position, downwards [m].
    double upper_punch_displacement = 0.0;
    /// Lower punch displacement from its initial position, upwards [m].
    double       lower_punch_displacement = 0.0;
    TabletForces forces;
    double       mean_relative_density = 0.0;
    unsigned int newton_iterations     = 0;
    /// Volume-averaged mean stress of the compact, tr(sigma) / 3 over its
    /// current volume [Pa], tension positive (TabletSolver::mean_stress()).
    /// In equilibrium it is the virial of the boundary tractions over the
    /// volume: for the tablet free of the die after ejection it is ~0
    /// whatever residual stress it holds (its parts, e.g. the FE2 floor's
    /// and the RVEs', need not be).
    double mean_stress = 0.0;
  };

  /**
   * Compaction (upper punch driven down, lower punch fixed), unloading
   * (upper punch withdrawn; the compact separates from it freely) and
   * ejection (upper punch removed, lower punch pushed up until the tablet
   * has left the die), in the given numbers of equal steps (a stage with
   * 0 steps is skipped). Calls
   * @p on_step after the initial state and after every converged step.
   * Returns false if a step did not converge; the solver then holds the
   * last converged state, which on_step has seen.
   *
   * @p resume_after > 0 continues a cycle whose steps up to that index
   * are done (the solver state restored from a checkpoint of that step):
   * the initial state is not reported again.
   */
  template <int dim>
  bool
  run_tablet_process(TabletSolver<dim>                             &solver,
                     const TabletProcess                           &process,
                     const std::function<void(const TabletStep &)> &on_step,
                     unsigned int resume_after = 0);

  /// Total number of steps of @p process (the initial state not counted).
  unsigned int
  n_steps(const TabletProcess &process);
} // namespace compax::fem

#include "dem/solver/relaxation.h"

#include "dem/solver/die_bed_system.h"
#include "dem/solver/stiffness_scaling.h"
#include "dem/wall_clock.h"

#include <limits>
#include <utility>

namespace compax::dem
{
  FireResult
  Relaxation::relax(Bed                &bed,
                    const ContactModel &model,
                    const double        target,
                    const int           budget,
                    const double        force_floor)
  {
    DieBedSystem system(bed, model, assembler);
    return relax(system, target, budget, force_floor);
  }

  void
  Relaxation::report_progress(RelaxationReport report_, const double interval)
  {
    report          = std::move(report_);
    report_interval = interval;
  }

  void
  Relaxation::give_up_when_stalled(const int window)
  {
    stall_window = window;
  }

  void
  Relaxation::start_watching()
  {
    started            = std::chrono::steady_clock::now();
    last_report        = started;
    stall_reference    = std::numeric_limits<double>::infinity();
    stall_reference_at = 0;
  }

  void
  Relaxation::record(FireResult              &result,
                     const RelaxationBalance &balance,
                     const int                evaluations)
  {
    result.record(balance, evaluations);
    const double distance = balance.balanced_below > 0.0
                              ? balance.largest_force / balance.balanced_below
                              : balance.largest_force;
    if (distance <= 0.5 * stall_reference) // the first is below infinity
      {
        stall_reference    = distance;
        stall_reference_at = evaluations;
      }
    result.stalled = !result.converged && stall_window > 0
                     && evaluations - stall_reference_at >= stall_window;
    if (!report || seconds_since(last_report) < report_interval)
      return;
    last_report = std::chrono::steady_clock::now();
    RelaxationProgress p;
    p.evaluations    = evaluations;
    p.seconds        = seconds_since(started);
    p.largest_force  = balance.largest_force;
    p.balanced_below = balance.balanced_below;
    report(p);
  }

  void
  Relaxation::assemble_inverse_diagonal(EquilibriumSystem &system,
                                        Eigen::VectorXd   &F,
                                        Eigen::VectorXd   &inverse_diagonal)
  {
    sums = system.assemble(F, K);
    inverse_diagonal_stiffness(K, system.n_particles(), inverse_diagonal);
  }
} // namespace compax::dem

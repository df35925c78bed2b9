#include "fem/tablet_process.h"

#include <algorithm>

namespace compax::fem
{
  std::string
  stage_name(const TabletStage stage)
  {
    switch (stage)
      {
        case TabletStage::compaction:
          return "compaction";
        case TabletStage::unloading:
          return "unloading";
        case TabletStage::ejection:
          return "ejection";
      }
    return "unknown";
  }

  unsigned int
  n_steps(const TabletProcess &p)
  {
    return std::max(1u, p.compaction_steps) + p.unloading_steps
           + p.ejection_steps;
  }

  template <int dim>
  bool
  run_tablet_process(TabletSolver<dim>                             &solver,
                     const TabletProcess                           &process,
                     const std::function<void(const TabletStep &)> &on_step,
                     const unsigned int resume_after)
  {
    const unsigned int nc = std::max(1u, process.compaction_steps);
    const unsigned int nu = process.unloading_steps;
    const unsigned int ne = process.ejection_steps;
    // Punch targets and cumulative punch travel after global step k.
    struct Target
    {
      TabletStage stage;
      double      upper, lower, travel;
      bool        upper_present;
    };
    const double fill   = solver.initial_upper_punch_position();
    const double bottom = fill - process.compaction_displacement;
    const double dc     = process.compaction_displacement / nc;
    const double du     = nu > 0 ? process.unloading_displacement / nu : 0.0;
    const double de     = ne > 0 ? process.ejection_displacement / ne : 0.0;
    auto         target = [&](const unsigned int k) -> Target {
      if (k <= nc)
        return {TabletStage::compaction, fill - dc * k, 0.0, dc * k, true};
      if (k <= nc + nu)
        return {TabletStage::unloading,
                bottom + du * (k - nc),
                0.0,
                dc * nc + du * (k - nc),
                true};
      return {TabletStage::ejection,
              bottom + du * nu,
              de * (k - nc - nu),
              dc * nc + du * nu + de * (k - nc - nu),
              false};
    };

    auto report =
      [&](const unsigned int k, const TabletStage stage, const double travel) {
        TabletStep step;
        step.index                    = k;
        step.stage                    = stage;
        step.time                     = travel / process.punch_speed;
        step.upper_punch_displacement = fill - solver.upper_punch_position();
        step.lower_punch_displacement = solver.lower_punch_position();
        step.forces                   = solver.forces();
        step.mean_relative_density    = solver.mean_relative_density();
        step.mean_stress       = dealii::trace(solver.mean_stress()) / 3.0;
        step.newton_iterations = k == 0 ? 0 : solver.last_iterations();
        on_step(step);
      };
    if (resume_after == 0)
      report(0, TabletStage::compaction, 0.0);
    for (unsigned int k = resume_after + 1; k <= nc + nu + ne; ++k)
      {
        const Target t = target(k);
        if (!solver.advance(t.upper, t.lower, t.upper_present))
          return false;
        report(k, t.stage, t.travel);
      }
    return true;
  }

  template bool
  run_tablet_process<2>(TabletSolver<2> &,
                        const TabletProcess &,
                        const std::function<void(const TabletStep &)> &,
                        unsigned int);
  template bool
  run_tablet_process<3>(TabletSolver<3> &,
                        const TabletProcess &,
                        const std::function<void(const TabletStep &)> &,
                        unsigned int);
} // namespace compax::fem

#pragma once
// The run and the check of the two-rank tablet tests: a distributed cycle
// gives the one-rank cycle's punch and die-wall forces (and, optionally,
// densities).
#include "fem/tablet_process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace compax::testing
{
  /// Every step of @p process on @p solver, which must complete the cycle.
  template <int dim>
  std::vector<fem::TabletStep>
  recorded_cycle(fem::TabletSolver<dim>   &solver,
                 const fem::TabletProcess &process)
  {
    std::vector<fem::TabletStep> steps;
    EXPECT_TRUE(fem::run_tablet_process<dim>(solver,
                                             process,
                                             [&](const fem::TabletStep &st) {
                                               steps.push_back(st);
                                             }));
    return steps;
  }

  /// Forces step by step within 1e-6 of the largest upper punch force
  /// (both runs converge to the Newton tolerance from different
  /// round-off); mean densities within @p density_tolerance if positive.
  inline void
  expect_equal_cycles(const std::vector<fem::TabletStep> &distributed,
                      const std::vector<fem::TabletStep> &serial,
                      const double density_tolerance = 0.0)
  {
    ASSERT_EQ(distributed.size(), serial.size());
    double scale = 0.0;
    for (const auto &st : serial)
      scale = std::max(scale, st.forces.upper_punch_force);
    ASSERT_GT(scale, 0.0);
    for (std::size_t k = 0; k < serial.size(); ++k)
      {
        const auto &a = distributed[k].forces, &b = serial[k].forces;
        EXPECT_NEAR(a.upper_punch_force, b.upper_punch_force, 1e-6 * scale)
          << "step " << k;
        EXPECT_NEAR(a.lower_punch_force, b.lower_punch_force, 1e-6 * scale)
          << "step " << k;
        EXPECT_NEAR(a.die_wall_normal_force,
                    b.die_wall_normal_force,
                    1e-6 * scale)
          << "step " << k;
        if (density_tolerance > 0.0)
          {
            EXPECT_NEAR(distributed[k].mean_relative_density,
                        serial[k].mean_relative_density,
                        density_tolerance)
              << "step " << k;
          }
      }
  }
} // namespace compax::testing

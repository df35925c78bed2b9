// A full tableting cycle of a Drucker-Prager Cap powder (MCC table):
// compaction to the in-die density that mass conservation predicts,
// unloading with residual die-wall pressure, and ejection whose force is
// the Coulomb friction of the sliding wall.
#include "fem/drucker_prager_cap.h"
#include "fem/tablet_process.h"
#include "mcc_tablet.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

namespace fem = compax::fem;

TEST(TabletDpcProcess, CompactionUnloadingEjection)
{
  const fem::TabletSolverSettings s = compax::testing::mcc_tablet_settings();
  const auto                      material = compax::testing::mcc_material();
  fem::TabletSolver<2>            solver(s, material, MPI_COMM_WORLD);
  fem::TabletProcess              process;
  process.compaction_steps = 40;
  process.unloading_steps  = 10;
  process.ejection_steps   = 30;
  std::vector<fem::TabletStep> steps;
  const bool                   ok
    = fem::run_tablet_process<2>(solver, process, [&](const auto &st) {
        steps.push_back(st);
      });
  ASSERT_TRUE(ok);
  ASSERT_EQ(steps.size(),
            1 + process.compaction_steps + process.unloading_steps
              + process.ejection_steps);

  // At the end of compaction the compact fills the rigid die between the
  // punches: mass conservation gives rho = rho_0 H_0 / (H_0 - travel), up
  // to the penalty penetration (pressure / penalty, ~1e-5 of the height).
  const fem::TabletStep &top = steps[process.compaction_steps];
  const double           H0  = s.geometry.fill_height;
  const double rho_max = 0.5 * H0 / (H0 - process.compaction_displacement);
  EXPECT_NEAR(top.mean_relative_density / rho_max, 1.0, 1e-3);
  // Axial equilibrium of the compact: the punch forces differ by the wall
  // friction, and the wall slides everywhere while the punch advances.
  EXPECT_NEAR((top.forces.upper_punch_force - top.forces.lower_punch_force)
                / top.forces.die_wall_friction_force,
              1.0,
              1e-6);
  EXPECT_NEAR(top.forces.die_wall_friction_force
                / (s.wall_friction * top.forces.die_wall_normal_force),
              1.0,
              1e-6);

  // After unloading the upper punch has separated and the die still holds
  // the compact radially.
  const fem::TabletStep &unloaded
    = steps[process.compaction_steps + process.unloading_steps];
  EXPECT_EQ(unloaded.forces.upper_punch_force, 0.0);
  EXPECT_GT(unloaded.forces.die_wall_normal_force,
            0.05 * top.forces.die_wall_normal_force);

  // Ejection: while the whole wall slides, the lower punch force is the
  // Coulomb friction mu N of the residual radial force N.
  unsigned int sliding_steps = 0;
  for (const auto &st : steps)
    if (st.stage == fem::TabletStage::ejection
        && st.forces.sliding_fraction == 1.0)
      {
        ++sliding_steps;
        EXPECT_NEAR(st.forces.lower_punch_force
                      / (s.wall_friction * st.forces.die_wall_normal_force),
                    1.0,
                    1e-6)
          << "step " << st.index;
      }
  EXPECT_GT(sliding_steps, process.ejection_steps / 2);
  // The tablet has left the die: no wall contact, no force.
  EXPECT_EQ(steps.back().forces.die_wall_normal_force, 0.0);
  EXPECT_LT(std::abs(steps.back().forces.lower_punch_force),
            1e-6 * top.forces.upper_punch_force);
}

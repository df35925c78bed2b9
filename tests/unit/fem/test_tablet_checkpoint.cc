// A cycle stopped at a checkpoint and resumed in a fresh solver ends in the
// state of the uninterrupted cycle.
#include "fem/drucker_prager_cap.h"
#include "fem/tablet_process.h"
#include "mcc_tablet.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <unistd.h>
#include <vector>

namespace fem = compax::fem;
using compax::testing::mcc_material;
using compax::testing::mcc_short_cycle;
using compax::testing::mcc_tablet_settings;

TEST(TabletCheckpoint, ResumedCycleEndsInTheUninterruptedState)
{
  const auto folder
    = std::filesystem::temp_directory_path()
      / ("compax-tablet-checkpoint-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);

  std::vector<fem::TabletStep> full;
  {
    fem::TabletSolver<2> solver(mcc_tablet_settings(),
                                mcc_material(),
                                MPI_COMM_SELF);
    ASSERT_TRUE(fem::run_tablet_process<2>(
      solver, mcc_short_cycle(), [&](const fem::TabletStep &st) {
        full.push_back(st);
        if (st.index == 22) // in the unloading stage
          solver.save_state(folder);
      }));
  }
  std::vector<fem::TabletStep> resumed;
  {
    fem::TabletSolver<2> solver(mcc_tablet_settings(),
                                mcc_material(),
                                MPI_COMM_SELF);
    solver.load_state(folder);
    ASSERT_TRUE(fem::run_tablet_process<2>(
      solver,
      mcc_short_cycle(),
      [&](const fem::TabletStep &st) { resumed.push_back(st); },
      22));
  }
  std::filesystem::remove_all(folder);
  ASSERT_EQ(resumed.size(), full.size() - 23);
  ASSERT_EQ(resumed.front().index, 23u);
  for (std::size_t k = 0; k < resumed.size(); ++k)
    {
      const auto &a = resumed[k], &b = full[k + 23];
      EXPECT_EQ(a.stage, b.stage);
      EXPECT_DOUBLE_EQ(a.time, b.time);
      EXPECT_DOUBLE_EQ(a.forces.lower_punch_force, b.forces.lower_punch_force);
      EXPECT_DOUBLE_EQ(a.forces.die_wall_normal_force,
                       b.forces.die_wall_normal_force);
      EXPECT_DOUBLE_EQ(a.mean_relative_density, b.mean_relative_density);
    }

  // A checkpoint of another mesh is refused.
  fem::TabletSolverSettings other = mcc_tablet_settings();
  other.geometry.n_radial_cells   = 5;
  fem::TabletSolver<2> solver(mcc_tablet_settings(),
                              mcc_material(),
                              MPI_COMM_SELF);
  std::filesystem::create_directories(folder);
  solver.save_state(folder);
  fem::TabletSolver<2> wrong(other, mcc_material(), MPI_COMM_SELF);
  EXPECT_THROW(wrong.load_state(folder), std::runtime_error);
  std::filesystem::remove_all(folder);
}

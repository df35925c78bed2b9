// The distributed model gives the punch forces of the one-rank model. Run
// as `mpirun -np 2 compax_fem_tests --gtest_filter='TabletMpi.*'` (ctest
// label mpi); on one rank it compares a run with itself.
#include "fem/drucker_prager_cap.h"
#include "fem/tablet_process.h"
#include "mcc_tablet.h"

#include "../../support/equal_tablet_cycles.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace fem = compax::fem;

namespace
{
  std::vector<fem::TabletStep>
  cycle(MPI_Comm comm)
  {
    fem::TabletSolver<2> solver(compax::testing::mcc_tablet_settings(6),
                                compax::testing::mcc_material(),
                                comm);
    fem::TabletProcess   p;
    p.compaction_displacement = 2.5e-3;
    p.compaction_steps        = 12;
    p.unloading_steps         = 4;
    p.ejection_displacement   = 1e-3;
    p.ejection_steps          = 4;
    return compax::testing::recorded_cycle(solver, p);
  }
} // namespace

TEST(TabletMpi, DistributedRunGivesSerialPunchForces)
{
  const auto distributed = cycle(MPI_COMM_WORLD);
  const auto serial      = cycle(MPI_COMM_SELF);
  compax::testing::expect_equal_cycles(distributed, serial, 1e-9);
}

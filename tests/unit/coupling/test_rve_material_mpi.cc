// The FE2 tablet distributed over MPI ranks gives the forces of the
// one-rank run: every rank initializes its points in the same order, so a
// point draws the same pool member whichever rank owns it, and each RVE
// is evaluated by its owner only. The RVEs are lattices (cheap and
// deterministic), two of them, so that a wrong draw would show. Run as `mpirun
// -np 2 compax_coupling_tests
// --gtest_filter='RveMaterialMpi.*'` (ctest label mpi); on one rank it
// compares a run with itself.
#include "coupling/rve_material.h"
#include "fe2_test_support.h"

#include "../../support/equal_tablet_cycles.h"
#include "fem/tablet_process.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

using namespace compax;

namespace
{
  constexpr double R = 100e-6;


  /// A frictional die whose points alternate between two lattices (two
  /// pool members of different preload), so that the solution is not
  /// uniform and a point must draw the same member on any rank.
  std::vector<fem::TabletStep>
  fe2_cycle(MPI_Comm comm)
  {
    const dem::ContactModel model = compax::testing::material1::contact_model();
    coupling::RveMaterialSpec spec;
    spec.pool
      = {compax::testing::simple_cubic_cell(2 * R - 0.010 * R, R, model),
         compax::testing::simple_cubic_cell(2 * R - 0.015 * R, R, model)};
    spec.compaction_axis = 1;
    // A lattice's stress is smooth: the continuum Newton balances it to its
    // own tolerance (the default resolution is that of random packings).
    spec.stress_resolution = 0.0;

    fem::TabletSolverSettings s;
    s.geometry.die_diameter    = 10e-3;
    s.geometry.fill_height     = 5e-3;
    s.geometry.n_radial_cells  = 2;
    s.wall_friction            = 0.2;
    s.initial_relative_density = spec.pool[1].relative_density();
    fem::TabletSolver<2> solver(
      s, std::make_shared<coupling::RveMaterial>(spec, model), comm);
    fem::TabletProcess p;
    p.compaction_displacement = 0.02e-3;
    p.compaction_steps        = 4;
    p.unloading_displacement  = 0.005e-3;
    p.unloading_steps         = 2;
    p.ejection_steps          = 0;
    p.ejection_displacement   = 0.0;
    return compax::testing::recorded_cycle(solver, p);
  }
} // namespace

TEST(RveMaterialMpi, DistributedFe2RunGivesSerialForces)
{
  const auto distributed = fe2_cycle(MPI_COMM_WORLD);
  const auto serial      = fe2_cycle(MPI_COMM_SELF);
  compax::testing::expect_equal_cycles(distributed, serial);
}

// The multiscale-database material over MPI ranks: one rank builds the
// database and reports it (so its files are written once), and every rank
// holds the same fitted table, the one of the study run on its own. Run as
// `mpirun -np 2 compax_coupling_tests
// --gtest_filter='MultiscaleDatabaseMpi.*'` (ctest label mpi); on one rank
// the single rank is the writer.
#include "coupling/multiscale_database_material.h"
#include "tests/support/gonzalez_material1.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <vector>

using namespace compax;

namespace
{
  coupling::DatabaseSpec
  small_spec()
  {
    coupling::DatabaseSpec spec;
    spec.packing.particle_count = 60;
    spec.packing.seed           = 3;
    spec.final_density          = 0.74;
    spec.branch_densities       = {0.68, 0.74};
    spec.shear_steps            = 4;
    spec.radial_ratios          = {};
    spec.denser_deposit         = dem::DenserDeposit::keep;
    // The subject is the single writer, not the fit. A 60-sphere cell is
    // too small for a robust cap fit: balanced by L-BFGS (the default) its
    // compaction state lies above its own shear line and the fit refuses
    // the table; the FIRE-balanced cell's fit holds.
    spec.loading.unjammed_equilibrium
      = dem::UnjammedEquilibrium::balanced_relaxation;
    return spec;
  }

  /// The table's parameters at its densities and between them.
  std::vector<double>
  table_values(const fem::DpcTable &table, const std::vector<double> &rho)
  {
    std::vector<double> v;
    for (const double r : rho)
      {
        const fem::DpcParameters p  = table.parameters(r);
        double                   pb = 0.0, dpb = 0.0;
        table.cap_pressure(r, pb, dpb);
        v.insert(v.end(),
                 {p.cohesion,
                  p.tan_friction_angle,
                  p.cap_eccentricity,
                  p.youngs_modulus,
                  p.poisson_ratio,
                  pb});
      }
    return v;
  }
} // namespace

TEST(MultiscaleDatabaseMpi, OneRankWritesAndEveryRankHoldsTheSameTable)
{
  const MPI_Comm          comm = MPI_COMM_WORLD;
  const unsigned int      rank = dealii::Utilities::MPI::this_mpi_process(comm);
  const dem::ContactModel model = compax::testing::material1::contact_model();
  const coupling::DatabaseSpec spec = small_spec();

  int                                  started = 0, progress = 0, built = 0;
  std::vector<coupling::DpcFitRow>     written;
  coupling::MultiscaleDatabaseObserver observer;
  observer.started  = [&] { ++started; };
  observer.progress = [&](const std::string &) { ++progress; };
  observer.built    = [&](const coupling::RveDatabaseStudyResult &r) {
    ++built;
    written = r.fit;
  };
  const auto material
    = coupling::make_multiscale_database_material(spec, model, comm, observer);
  ASSERT_TRUE(material);

  // One writer: rank 0 reports and is handed the database, no other rank.
  EXPECT_EQ(dealii::Utilities::MPI::sum(built, comm), 1);
  EXPECT_EQ(dealii::Utilities::MPI::sum(started, comm), 1);
  EXPECT_EQ(built, rank == 0 ? 1 : 0);
  EXPECT_EQ(started, rank == 0 ? 1 : 0);
  if (rank == 0)
    EXPECT_GT(progress, 0);
  else
    EXPECT_EQ(progress, 0);

  // Equal materials: every rank's table is rank 0's, bit for bit ...
  const std::vector<double> rho  = {0.60, 0.68, 0.71, 0.74, 0.80};
  const std::vector<double> mine = table_values(material->table(), rho);
  const std::vector<double> root
    = dealii::Utilities::MPI::broadcast(comm, mine, 0);
  EXPECT_EQ(mine, root) << "rank " << rank;
  // ... and the table of the fit the writer was handed, which is that of
  // the study run on one process.
  if (rank == 0)
    {
      EXPECT_EQ(mine, table_values(coupling::to_dpc_table(written), rho));
      coupling::RveDatabaseStudyOptions options;
      options.spec     = spec;
      options.validate = false;
      const auto alone = coupling::RveDatabaseStudy(model, options).run();
      ASSERT_EQ(alone.outcome, coupling::RveDatabaseOutcome::complete);
      EXPECT_EQ(mine, table_values(coupling::to_dpc_table(alone.fit), rho));
    }
}

// The HDF5/XDMF field output of the tablet model reopens with the mesh's
// node count and a relative density in its physical range.
#include "fem/drucker_prager_cap.h"
#include "fem/tablet_solver.h"
#include "mcc_tablet.h"

#include <deal.II/base/hdf5.h>
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace fem = compax::fem;

TEST(TabletHdf5Output, FieldsReopenWithTheMeshAndAPhysicalDensity)
{
  // One folder for all ranks: rank 0's name.
  const std::filesystem::path folder
    = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD,
                                        (std::filesystem::temp_directory_path()
                                         / ("compax-hdf5-"
                                            + std::to_string(::getpid())))
                                          .string(),
                                        0);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::create_directories(folder);
  MPI_Barrier(MPI_COMM_WORLD);

  const fem::TabletSolverSettings s    = compax::testing::mcc_tablet_settings();
  const double                    rho0 = s.initial_relative_density;
  fem::TabletSolver<2>            solver(s,
                              compax::testing::mcc_material(),
                              MPI_COMM_WORLD);
  std::vector<dealii::XDMFEntry>  entries;
  for (unsigned int step = 1; step <= 4; ++step)
    {
      ASSERT_TRUE(solver.advance(7e-3 - step * 0.25e-3, 0.0));
      const fem::FieldFiles files
        = solver.write_fields(folder, step, 0.01 * step, false, true);
      EXPECT_TRUE(files.vtu_record.empty());
      EXPECT_EQ(files.hdf5_file, "tablet_000" + std::to_string(step) + ".h5");
      entries.push_back(files.xdmf);
    }
  fem::write_xdmf_record<2>(entries, folder / "tablet.xdmf", MPI_COMM_WORLD);
  const double mean_density = solver.mean_relative_density(); // collective
  MPI_Barrier(MPI_COMM_WORLD);

  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      // Every cell writes its own 4 nodes, so that the cell fields are
      // exact; each node has x, y (and a zero z in 2-D files).
      const std::size_t  n_nodes = 4 * solver.n_cells();
      dealii::HDF5::File h5((folder / "tablet_0004.h5").string(),
                            dealii::HDF5::File::FileAccessMode::open);
      const auto         nodes = h5.open_dataset("nodes").get_dimensions();
      ASSERT_GE(nodes.size(), 1u);
      EXPECT_EQ(nodes[0], n_nodes);
      const auto cells = h5.open_dataset("cells").get_dimensions();
      EXPECT_EQ(cells[0], solver.n_cells());

      const auto rho
        = h5.open_dataset("relative_density").read<std::vector<double>>();
      ASSERT_EQ(rho.size(), n_nodes);
      const auto [lo, hi] = std::minmax_element(rho.begin(), rho.end());
      // Compaction only densifies, and no powder exceeds full density.
      EXPECT_GE(*lo, rho0 * (1.0 - 1e-6));
      EXPECT_LE(*hi, 1.0);
      EXPECT_GT(*hi, rho0);
      // The density is mass over volume: its mean over the nodes (each
      // cell's value four times) is close to the solver's mean density.
      double sum = 0.0;
      for (const double r : rho)
        sum += r;
      EXPECT_NEAR(sum / n_nodes, mean_density, 0.05);

      // The .xdmf lists the four steps.
      std::ifstream      in(folder / "tablet.xdmf");
      std::ostringstream text;
      text << in.rdbuf();
      for (unsigned int step = 1; step <= 4; ++step)
        EXPECT_NE(text.str().find("tablet_000" + std::to_string(step)
                                  + ".h5:/relative_density"),
                  std::string::npos);
      std::filesystem::remove_all(folder);
    }
  MPI_Barrier(MPI_COMM_WORLD);
}

// MPI (and p4est/Trilinos/HDF5) initialisation for a whole test binary. The
// executable's main comes from GTest::gtest_main, so a global Environment
// registered by a static object does it: gtest runs SetUp() before the first
// test and TearDown() after the last, and never for --gtest_list_tests, so
// test discovery starts no MPI. Each ctest process is a singleton MPI run.
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <memory>

namespace
{
  class MpiEnvironment : public ::testing::Environment
  {
  public:
    void
    SetUp() override
    {
      static int    argc   = 1;
      static char   name[] = "compax_tests";
      static char  *args[] = {name, nullptr};
      static char **argv   = args;
      mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(
        argc, argv, /*max_num_threads=*/1);
    }

    void
    TearDown() override
    {
      mpi.reset();
    }

  private:
    std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  };

  [[maybe_unused]] ::testing::Environment *const mpi_environment
    = ::testing::AddGlobalTestEnvironment(new MpiEnvironment);
} // namespace

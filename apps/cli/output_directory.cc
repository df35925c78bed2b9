#include "apps/cli/output_directory.h"

#include "apps/cli/input_error.h"

#include <deal.II/base/mpi.h>

#include <system_error>

namespace compax::cli
{
  namespace
  {
    /// Under mpirun only rank 0 creates, publishes and removes the folder;
    /// every rank writes its pieces into the same staging path.
    bool
    is_root()
    {
      return !dealii::Utilities::MPI::job_supports_mpi()
             || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    }

    void
    barrier()
    {
      if (dealii::Utilities::MPI::job_supports_mpi())
        MPI_Barrier(MPI_COMM_WORLD);
    }
  } // namespace

  OutputDirectory::OutputDirectory(std::filesystem::path path)
      : final_path(std::move(path))
  {
    namespace fs            = std::filesystem;
    const fs::path absolute = fs::absolute(final_path).lexically_normal();
    fs::path       parent   = absolute.parent_path();
    std::string    name     = absolute.filename().string();
    if (name.empty())
      {
        name   = absolute.parent_path().filename().string();
        parent = absolute.parent_path().parent_path();
      }
    std::error_code error;
    fs::create_directories(parent, error);
    if (error)
      throw InputError("output folder '" + final_path.string()
                       + "': cannot create its parent folder ("
                       + error.message() + ")");
    staging_path
      = parent / ("." + name + ".partial-" + std::to_string(::getpid()));
    fs::remove_all(staging_path, error);
    fs::create_directory(staging_path, error);
    if (error)
      throw InputError("output folder '" + final_path.string()
                       + "': cannot be created (" + error.message() + ")");
    final_path = parent / name;
  }

  OutputDirectory::~OutputDirectory()
  {
    if (!published && is_root())
      {
        std::error_code ignored;
        std::filesystem::remove_all(staging_path, ignored);
      }
  }

  void
  OutputDirectory::publish()
  {
    barrier();
    if (is_root())
      {
        std::filesystem::remove_all(final_path);
        std::filesystem::rename(staging_path, final_path);
      }
    published = true;
  }

  void
  OutputDirectory::publish_partial()
  {
    publish();
  }
} // namespace compax::cli

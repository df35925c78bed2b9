#include "coupling/die_state_archive.h"

#include "coupling/bed_archive.h"
#include "coupling/hdf5_archive.h"

#include <stdexcept>

namespace compax::coupling
{
  void
  write_die_branch_checkpoint(const std::string &file,
                              const std::string &parameters,
                              const dem::Bed    &bed,
                              const int          branch)
  {
    write_archive(file,
                  {archive_kind::die_branch, parameters},
                  [&](Hdf5ArchiveWriter &archive) {
                    archive.write_attribute("relative_density",
                                            bed.relative_density());
                    archive.write_attribute("branch", double(branch));
                    save_bed(archive, "bed", bed);
                  });
  }

  DieBranchState
  read_die_branch_checkpoint(const std::string       &file,
                             const std::string       &parameters,
                             const dem::ContactModel &model)
  {
    const Hdf5ArchiveReader archive(file, archive_kind::die_branch, parameters);
    const double            k = archive.read_attribute("branch");
    if (!(k >= 1 && k <= 1e6))
      throw std::runtime_error("no branch number");
    return {load_bed(archive, "bed", model), static_cast<int>(k)};
  }

  void
  write_die_state(const std::string &file,
                  const std::string &parameters,
                  const dem::Bed    &bed,
                  const std::string &failure)
  {
    write_archive(file,
                  {archive_kind::die_state, parameters},
                  [&](Hdf5ArchiveWriter &archive) {
                    archive.write_attribute("failure", failure);
                    save_bed(archive, "bed", bed);
                  });
  }
} // namespace compax::coupling

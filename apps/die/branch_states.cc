#include "apps/die/branch_states.h"

#include "apps/die/bed_checkpoint.h"
#include "dem/analysis/bed_statistics.h"
#include "dem/analysis/fabric.h"
#include "dem/io/particle_vtu.h"

#include <cmath>

namespace compax::cli
{
  BranchStateWriter::BranchStateWriter(const std::filesystem::path &folder)
      : folder(folder)
      , fabric(folder / "fabric.csv",
               {"branch",
                "stage",
                "relative_density",
                "contacts",
                "a20",
                "a40",
                "a60",
                "a80",
                "b20",
                "b40",
                "b60",
                "b80"})
      , histograms(folder / "force_histograms.csv",
                   {"branch", "stage", "force", "count"})
  {
    std::filesystem::create_directories(folder / "snapshots");
    std::filesystem::create_directories(folder / "checkpoints");
  }

  void
  BranchStateWriter::operator()(const dem::Bed    &bed,
                                const std::string &stage,
                                const int          branch)
  {
    const std::string name = stage + "-" + std::to_string(branch);
    dem::write_particles_vtu(folder / "snapshots" / (name + ".vtu"), bed);
    // Time-like key: branch, then the stage within it.
    const double key = branch
                       + (stage == "compaction"  ? 0.0
                          : stage == "unloading" ? 0.3
                                                 : 0.6);
    snapshots.emplace_back(key, "snapshots/" + name + ".vtu");
    dem::write_pvd(folder / "particles.pvd", snapshots);

    const auto          network = dem::loaded_contacts(bed);
    std::vector<double> magnitude(network.forces.size());
    for (std::size_t c = 0; c < magnitude.size(); ++c)
      magnitude[c] = std::abs(network.forces[c]);
    if (network.forces.size() >= 4)
      {
        const auto spectrum = dem::fit_fabric(network.normals, magnitude);
        fabric << branch << stage << bed.relative_density()
               << static_cast<long long>(network.forces.size());
        for (double a : spectrum.a)
          fabric << a;
        for (double b : spectrum.b)
          fabric << b;
        fabric.end_row();
      }
    const auto histogram = dem::force_histogram(network.forces, 30);
    for (std::size_t k = 0; k < histogram.counts.size(); ++k)
      {
        histograms << branch << stage << histogram.centres[k]
                   << static_cast<long long>(histogram.counts[k]);
        histograms.end_row();
      }

    if (stage == "compaction")
      {
        coupling::Hdf5ArchiveWriter archive(
          (folder / "checkpoints"
           / ("branch-" + std::to_string(branch) + ".h5"))
            .string());
        archive.write_attribute("format", "compax die bed state 1");
        archive.write_attribute("relative_density", bed.relative_density());
        save_bed(archive, "bed", bed);
        archive.commit();
      }
  }
} // namespace compax::cli

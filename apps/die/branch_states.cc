#include "apps/die/branch_states.h"

#include "apps/die/bed_checkpoint.h"
#include "dem/analysis/bed_statistics.h"
#include "dem/analysis/fabric.h"
#include "dem/io/particle_vtu.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

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
  BranchStateWriter::add_snapshot(const std::string &stage, const int branch)
  {
    // Time-like key: branch, then the stage within it.
    const double key = branch
                       + (stage == "compaction"  ? 0.0
                          : stage == "unloading" ? 0.3
                                                 : 0.6);
    snapshots.emplace_back(key,
                           "snapshots/" + stage + "-" + std::to_string(branch)
                             + ".vtu");
    dem::write_pvd(folder / "particles.pvd", snapshots);
  }

  int
  BranchStateWriter::carry_over(const std::filesystem::path &old_folder,
                                const int                    branches)
  {
    namespace fs = std::filesystem;
    int  missing = 0;
    auto copy    = [&](const fs::path &relative) {
      std::error_code error;
      fs::copy_file(old_folder / relative,
                    folder / relative,
                    fs::copy_options::overwrite_existing,
                    error);
      if (error)
        ++missing;
      return !error;
    };
    for (int b = 1; b <= branches; ++b)
      {
        for (const char *stage : {"compaction", "unloading", "ejection"})
          if (copy(fs::path("snapshots")
                   / (std::string(stage) + "-" + std::to_string(b) + ".vtu")))
            add_snapshot(stage, b);
        copy(fs::path("checkpoints") / ("branch-" + std::to_string(b) + ".h5"));
      }
    // Rows of the per-branch tables whose first cell (branch) is done.
    for (auto [name, table] : {std::pair{"fabric.csv", &fabric},
                               std::pair{"force_histograms.csv", &histograms}})
      {
        std::ifstream in(old_folder / name);
        if (!in)
          {
            ++missing;
            continue;
          }
        std::string line;
        std::getline(in, line); // header
        while (std::getline(in, line))
          {
            if (line.empty() || std::atoi(line.c_str()) > branches)
              continue;
            std::istringstream cells(line);
            for (std::string cell; std::getline(cells, cell, ',');)
              *table << cell;
            if (line.back() == ',')
              table->empty();
            table->end_row();
          }
      }
    return missing;
  }

  void
  BranchStateWriter::operator()(const dem::Bed    &bed,
                                const std::string &stage,
                                const int          branch)
  {
    const std::string name = stage + "-" + std::to_string(branch);
    dem::write_particles_vtu(folder / "snapshots" / (name + ".vtu"), bed);
    add_snapshot(stage, branch);

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

#include "apps/die/branch_states.h"

#include "coupling/die_state_archive.h"
#include "coupling/hdf5_archive.h"
#include "dem/analysis/bed_statistics.h"
#include "dem/analysis/fabric.h"
#include "dem/io/particle_vtu.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace compax::cli
{
  BranchStateWriter::BranchStateWriter(const std::filesystem::path &folder,
                                       std::string state_parameters)
      : folder(folder)
      , state_parameters(std::move(state_parameters))
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

  coupling::DieBranchFiles
  BranchStateWriter::so_far()
  {
    fabric.flush();
    histograms.flush();
    return written;
  }

  void
  BranchStateWriter::verify(const std::filesystem::path    &old_folder,
                            const coupling::DieBranchFiles &earlier)
  {
    namespace fs = std::filesystem;
    for (const auto &[name, hash] : earlier.files)
      {
        const fs::path from = old_folder / name;
        if (!fs::is_regular_file(from))
          throw std::runtime_error(
            "the earlier branches' file '" + name
            + "' is not next to the checkpoint (in '" + old_folder.string()
            + "'); resume from the checkpoint in its run folder");
        if (coupling::file_hash(from.string()) != hash)
          throw std::runtime_error("the earlier branches' file '"
                                   + from.string()
                                   + "' differs from the one the checkpoint "
                                     "lists (changed since)");
      }
  }

  void
  BranchStateWriter::carry_over(const std::filesystem::path    &old_folder,
                                const coupling::DieBranchFiles &earlier)
  {
    namespace fs = std::filesystem;
    verify(old_folder, earlier);
    for (const auto &[name, hash] : earlier.files)
      {
        const fs::path from = old_folder / name;
        fs::create_directories((folder / name).parent_path());
        fs::copy_file(from,
                      folder / name,
                      fs::copy_options::overwrite_existing);
        written.files.emplace_back(name, hash);
        // snapshots/<stage>-<branch>.vtu
        const std::string stem = fs::path(name).stem().string();
        const auto        dash = stem.rfind('-');
        if (fs::path(name).extension() == ".vtu" && dash != std::string::npos)
          add_snapshot(stem.substr(0, dash),
                       std::atoi(stem.c_str() + dash + 1));
      }
    for (auto [text, table] : {std::pair{&earlier.fabric_rows, &fabric},
                               std::pair{&earlier.histogram_rows, &histograms}})
      {
        std::istringstream lines(*text);
        for (std::string line; std::getline(lines, line);)
          table->add_row_text(line);
      }
    written.fabric_rows += earlier.fabric_rows;
    written.histogram_rows += earlier.histogram_rows;
  }

  void
  BranchStateWriter::operator()(const dem::Bed    &bed,
                                const std::string &stage,
                                const int          branch)
  {
    const std::string name = stage + "-" + std::to_string(branch);
    dem::write_particles_vtu(folder / "snapshots" / (name + ".vtu"), bed);
    add_snapshot(stage, branch);
    const std::string snapshot = "snapshots/" + name + ".vtu";
    written.files.emplace_back(
      snapshot, coupling::file_hash((folder / snapshot).string()));

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
        written.fabric_rows += fabric.last_row() + "\n";
      }
    const auto histogram = dem::force_histogram(network.forces, 30);
    for (std::size_t k = 0; k < histogram.counts.size(); ++k)
      {
        histograms << branch << stage << histogram.centres[k]
                   << static_cast<long long>(histogram.counts[k]);
        histograms.end_row();
        written.histogram_rows += histograms.last_row() + "\n";
      }

    if (stage == "compaction")
      {
        const std::string checkpoint
          = "checkpoints/branch-" + std::to_string(branch) + ".h5";
        coupling::write_die_branch_checkpoint((folder / checkpoint).string(),
                                              state_parameters,
                                              bed,
                                              branch);
        written.files.emplace_back(
          checkpoint, coupling::file_hash((folder / checkpoint).string()));
      }
  }
} // namespace compax::cli

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
  void
  save_branch_files(coupling::Hdf5ArchiveWriter &archive,
                    const std::string           &group,
                    const BranchFiles           &files)
  {
    archive.write_text(group + "/fabric_rows", files.fabric_rows);
    archive.write_text(group + "/histogram_rows", files.histogram_rows);
    std::string list;
    for (const auto &[name, hash] : files.files)
      list += hash + " " + name + "\n";
    archive.write_text(group + "/files", list);
  }

  BranchFiles
  load_branch_files(const coupling::Hdf5ArchiveReader &archive,
                    const std::string                 &group)
  {
    BranchFiles files;
    files.fabric_rows    = archive.read_text(group + "/fabric_rows");
    files.histogram_rows = archive.read_text(group + "/histogram_rows");
    std::istringstream list(archive.read_text(group + "/files"));
    for (std::string line; std::getline(list, line);)
      {
        const auto        space = line.find(' ');
        const std::string name
          = space == std::string::npos ? "" : line.substr(space + 1);
        if (space != 16 || name.empty() || name.front() == '/'
            || name.find("..") != std::string::npos)
          throw std::runtime_error("malformed list of branch files");
        files.files.emplace_back(name, line.substr(0, space));
      }
    return files;
  }

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

  BranchFiles
  BranchStateWriter::so_far()
  {
    fabric.flush();
    histograms.flush();
    return written;
  }

  void
  BranchStateWriter::verify(const std::filesystem::path &old_folder,
                            const BranchFiles           &earlier)
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
  BranchStateWriter::carry_over(const std::filesystem::path &old_folder,
                                const BranchFiles           &earlier)
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
        coupling::Hdf5ArchiveWriter archive((folder / checkpoint).string(),
                                            {coupling::archive_kind::die_branch,
                                             state_parameters});
        archive.write_attribute("relative_density", bed.relative_density());
        archive.write_attribute("branch", double(branch));
        save_bed(archive, "bed", bed);
        archive.commit();
        written.files.emplace_back(
          checkpoint, coupling::file_hash((folder / checkpoint).string()));
      }
  }
} // namespace compax::cli

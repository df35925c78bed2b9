#include "coupling/tablet_checkpoint.h"

#include "coupling/hdf5_archive.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace compax::coupling
{
  namespace
  {
    constexpr std::size_t step_fields = 14;

    std::vector<double>
    pack(const fem::TabletStep &s)
    {
      const auto &f = s.forces;
      return {double(s.index),
              s.time,
              double(static_cast<int>(s.stage)),
              s.upper_punch_displacement,
              s.lower_punch_displacement,
              f.upper_punch_force,
              f.lower_punch_force,
              f.die_wall_normal_force,
              f.die_wall_contact_area,
              f.die_wall_friction_force,
              f.sliding_fraction,
              s.mean_relative_density,
              double(s.newton_iterations),
              s.mean_stress};
    }

    fem::TabletStep
    unpack(const double *v)
    {
      const auto whole = [](double x, double max) {
        if (!(x >= 0 && x <= max && x == std::floor(x)))
          throw std::runtime_error("malformed step table");
        return static_cast<unsigned int>(x);
      };
      fem::TabletStep s;
      s.index = whole(v[0], 1e9);
      s.time  = v[1];
      s.stage = static_cast<fem::TabletStage>(whole(v[2], 2));
      s.upper_punch_displacement       = v[3];
      s.lower_punch_displacement       = v[4];
      s.forces.upper_punch_force       = v[5];
      s.forces.lower_punch_force       = v[6];
      s.forces.die_wall_normal_force   = v[7];
      s.forces.die_wall_contact_area   = v[8];
      s.forces.die_wall_friction_force = v[9];
      s.forces.sliding_fraction        = v[10];
      s.mean_relative_density          = v[11];
      s.newton_iterations              = whole(v[12], 1e9);
      // 0 in checkpoints written before the column existed.
      s.mean_stress = v[13];
      return s;
    }
  } // namespace

  void
  write_tablet_checkpoint(const std::filesystem::path &folder,
                          const std::string           &parameters,
                          const unsigned int           ranks,
                          const TabletCheckpoint      &checkpoint)
  {
    namespace fs = std::filesystem;
    Hdf5ArchiveWriter archive((folder / "tablet.h5").string(),
                              {archive_kind::tablet, parameters});
    archive.write_attribute("ranks", double(ranks));
    std::vector<double> steps;
    for (const auto &s : checkpoint.steps)
      for (const double v : pack(s))
        steps.push_back(v);
    archive.write_array("steps", steps, {checkpoint.steps.size(), step_fields});
    archive.write_text("fields", checkpoint.fields);
    archive.write_text("xdmf", checkpoint.xdmf);
    // The solver states beside it, by content.
    std::vector<std::string> names;
    for (const auto &e : fs::directory_iterator(folder))
      {
        const std::string name = e.path().filename().string();
        if (e.is_regular_file() && name != "tablet.h5"
            && name != "tablet.h5.tmp")
          names.push_back(name);
      }
    std::sort(names.begin(), names.end());
    std::string list;
    for (const std::string &name : names)
      list += file_hash((folder / name).string()) + " " + name + "\n";
    archive.write_text("files", list);
    archive.commit();
  }

  TabletCheckpoint
  read_tablet_checkpoint(const std::filesystem::path      &folder,
                         const std::string                &parameters,
                         const std::optional<unsigned int> ranks)
  {
    const std::string       path    = (folder / "tablet.h5").string();
    const Hdf5ArchiveReader archive = [&] {
      try
        {
          return open_archive(path, archive_kind::tablet, parameters);
        }
      catch (const Hdf5ArchiveError &e)
        {
          // Named from the run folder that Resume from gives.
          throw Hdf5ArchiveError(path, "checkpoint/tablet.h5 " + e.reason());
        }
    }();
    const double written = archive.read_attribute("ranks");
    if (ranks && written != double(*ranks))
      throw Hdf5ArchiveError(path,
                             "checkpoint/tablet.h5 was written by a run on "
                               + std::to_string(std::llround(written))
                               + " MPI rank(s), this run has "
                               + std::to_string(*ranks)
                               + " (resume on as many ranks)");
    TabletCheckpoint c;
    const auto       steps = archive.read_array("steps");
    if (steps.empty() || steps.size() % step_fields != 0)
      throw std::runtime_error("malformed step table");
    for (std::size_t k = 0; k < steps.size(); k += step_fields)
      c.steps.push_back(unpack(&steps[k]));
    c.fields = archive.read_text("fields");
    c.xdmf   = archive.read_text("xdmf");
    std::istringstream list(archive.read_text("files"));
    for (std::string line; std::getline(list, line);)
      {
        const auto        space = line.find(' ');
        const std::string name
          = space == std::string::npos ? "" : line.substr(space + 1);
        if (space != 16 || name.empty() || name.find('/') != std::string::npos)
          throw std::runtime_error("malformed file list");
        const std::string hash = file_hash((folder / name).string());
        if (hash.empty())
          throw Hdf5ArchiveError(path,
                                 "checkpoint/tablet.h5: its file '" + name
                                   + "' is missing");
        if (hash != line.substr(0, space))
          throw Hdf5ArchiveError(
            path,
            "checkpoint/tablet.h5: its file '" + name
              + "' differs from the one it was written with (damaged)");
      }
    return c;
  }

  TabletCheckpoint
  read_tablet_resume(const std::filesystem::path      &run_folder,
                     const std::string                &parameters,
                     const std::optional<unsigned int> ranks)
  {
    namespace fs = std::filesystem;
    if (!fs::is_directory(run_folder))
      throw TabletResumeError(fs::exists(run_folder)
                                ? "is not a folder (give the output folder "
                                  "of the earlier run)"
                                : "no such folder");
    if (!fs::is_directory(run_folder / "checkpoint"))
      throw TabletResumeError(
        "has no checkpoint folder (run with Checkpoint interval > 0)");
    try
      {
        return read_tablet_checkpoint(run_folder / "checkpoint",
                                      parameters,
                                      ranks);
      }
    catch (const Hdf5ArchiveError &e)
      {
        throw TabletResumeError(e.reason());
      }
    catch (const std::exception &e)
      {
        // Content that does not fit together.
        throw TabletResumeError("a damaged "
                                + describe_archive_kind(archive_kind::tablet)
                                + " (" + e.what() + ")");
      }
  }
} // namespace compax::coupling

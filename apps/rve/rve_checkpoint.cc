#include "apps/rve/rve_checkpoint.h"

#include "apps/cli/archive_entry.h"
#include "apps/cli/input_error.h"
#include "apps/rve/rve_snapshot.h"
#include "apps/rve/rve_tables.h"
#include "coupling/rve_archive.h"

#include <sstream>
#include <stdexcept>

namespace compax::cli
{
  namespace
  {
    std::vector<double>
    flatten(const std::vector<std::vector<double>> &rows, std::size_t width)
    {
      std::vector<double> v;
      v.reserve(rows.size() * width);
      for (const auto &r : rows)
        v.insert(v.end(), r.begin(), r.end());
      return v;
    }

    std::vector<std::vector<double>>
    unflatten(const std::vector<double> &v, std::size_t width)
    {
      if (width == 0 || v.size() % width != 0)
        throw std::runtime_error("malformed table");
      std::vector<std::vector<double>> rows;
      for (std::size_t k = 0; k < v.size(); k += width)
        rows.emplace_back(v.begin() + k, v.begin() + k + width);
      return rows;
    }
  } // namespace

  void
  write_rve_checkpoint(const std::filesystem::path &file,
                       const coupling::RveStudy    &study,
                       const dem::PeriodicBed      &bed,
                       const RveProgress           &p)
  {
    std::filesystem::create_directories(file.parent_path());
    coupling::Hdf5ArchiveWriter archive(file.string(),
                                        {coupling::archive_kind::rve,
                                         study.resume_parameters});
    coupling::save_rve(archive, "rve", bed);
    archive.write_array("rows",
                        flatten(p.rows, rve_columns().size()),
                        {p.rows.size(), rve_columns().size()});
    archive.write_array("moduli",
                        flatten(p.moduli, moduli_columns().size()),
                        {p.moduli.size(), moduli_columns().size()});
    archive.write_array("snapshots",
                        std::vector<double>(p.snapshots.begin(),
                                            p.snapshots.end()));
    // The snapshots so far, by content: a resumed run takes them over.
    std::string hashes;
    for (const int s : p.snapshots)
      hashes
        += coupling::file_hash(
             (file.parent_path().parent_path() / snapshot_name(s)).string())
           + "\n";
    archive.write_text("snapshot_hashes", hashes);
    std::vector<double> F(9);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        F[3 * r + c] = p.loaded_deformation(r, c);
    archive.write_array("loaded_deformation", F, {3, 3});
    archive.commit();
  }

  RveProgress
  read_rve_checkpoint(const std::string        &file,
                      const coupling::RveStudy &study,
                      dem::PeriodicBed         &bed)
  {
    const std::string entry = "Checkpoints/Resume from";
    RveProgress       p;
    read_archive_entry(entry, file, coupling::archive_kind::rve, [&] {
      const coupling::Hdf5ArchiveReader archive(file,
                                                coupling::archive_kind::rve,
                                                study.resume_parameters);
      bed    = coupling::load_rve(archive, "rve", study.model);
      p.rows = unflatten(archive.read_array("rows"), rve_columns().size());
      p.moduli
        = unflatten(archive.read_array("moduli"), moduli_columns().size());
      for (const double s : archive.read_array("snapshots"))
        {
          if (!(s >= 0 && s <= 1e9))
            throw std::runtime_error("malformed snapshot list");
          p.snapshots.push_back(static_cast<int>(s));
        }
      std::istringstream hashes(archive.read_text("snapshot_hashes"));
      for (std::string h; std::getline(hashes, h);)
        p.snapshot_hashes.push_back(h);
      if (p.snapshot_hashes.size() != p.snapshots.size())
        throw std::runtime_error("malformed snapshot list");
      const auto F = archive.read_array("loaded_deformation");
      if (F.size() != 9)
        throw std::runtime_error("malformed loaded deformation");
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          p.loaded_deformation(r, c) = F[3 * r + c];
      if (p.rows.empty())
        throw std::runtime_error("no rows");
      for (const auto &row : p.rows)
        if (!(row[rve_column("step")] >= 0 && row[rve_column("step")] <= 1e9))
          throw std::runtime_error("malformed rows");
    });
    // The snapshots of the earlier part, next to the checkpoint.
    const auto old_folder
      = std::filesystem::absolute(file).parent_path().parent_path();
    for (std::size_t k = 0; k < p.snapshots.size(); ++k)
      {
        const auto from = old_folder / snapshot_name(p.snapshots[k]);
        if (!std::filesystem::is_regular_file(from))
          reject_entry(entry,
                       file,
                       "the earlier snapshot '" + snapshot_name(p.snapshots[k])
                         + "' is not next to the checkpoint (in '"
                         + old_folder.string()
                         + "'); resume from the checkpoint in its run folder");
        if (coupling::file_hash(from.string()) != p.snapshot_hashes[k])
          reject_entry(entry,
                       file,
                       "the earlier snapshot '" + from.string()
                         + "' differs from the one the checkpoint lists "
                           "(changed since)");
      }
    return p;
  }

  dem::RvePathState
  resumed_state(dem::PeriodicBed   bed,
                const RveProgress &progress,
                const double       jamming_pressure)
  {
    const std::size_t c_stage = rve_column("stage");
    const std::size_t c_p     = rve_column("mean_pressure");
    dem::RvePathState s{std::move(bed)};
    s.started = true;
    for (const auto &row : progress.rows)
      {
        if (row[rve_column("step")] > 0)
          (row[c_stage] == 0.0 ? s.loading_done : s.unloading_done) += 1;
        if (row[c_p] >= jamming_pressure)
          s.jammed = true;
      }
    const auto &last  = progress.rows.back();
    s.initial_density = progress.rows.front()[rve_column("relative_density")];
    s.unloading       = last[c_stage] != 0.0;
    s.axial_stress    = last[rve_column("sigma_zz")];
    s.mean_pressure   = last[c_p];
    s.loaded_deformation = progress.loaded_deformation;
    return s;
  }
} // namespace compax::cli

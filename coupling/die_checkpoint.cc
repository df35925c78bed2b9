#include "coupling/die_checkpoint.h"

#include "coupling/bed_archive.h"
#include "coupling/hdf5_archive.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace compax::coupling
{
  namespace
  {
    const char *const stages[] = {"compaction", "unloading", "ejection"};

    double
    stage_code(const std::string &stage)
    {
      for (int k = 0; k < 3; ++k)
        if (stage == stages[k])
          return k;
      throw std::runtime_error("unknown die stage '" + stage + "'");
    }

    /// The numbers of a die.csv row, in a fixed order (the stage as its
    /// index in `stages`). The same list reads and writes.
    template <typename Record, typename Visit>
    void
    for_each_field(Record &r, Visit &&visit)
    {
      visit(r.branch);
      visit(r.step);
      visit(r.punch_gap);
      visit(r.relative_density);
      visit(r.rho_max_in_die);
      visit(r.rho_min_in_die);
      visit(r.rho_tablet);
      visit(r.upper_punch_force);
      visit(r.lower_punch_force);
      visit(r.die_wall_force);
      visit(r.upper_punch_pressure);
      visit(r.lower_punch_pressure);
      visit(r.die_wall_pressure);
      visit(r.coordination_number);
      visit(r.bonding_surface);
      visit(r.bonds);
      visit(r.bonds_formed);
      visit(r.bonds_broken);
      visit(r.elastic_recovery_rho);
      visit(r.elastic_recovery_H);
      visit(r.residual_radial_pressure);
      visit(r.ejection_pressure);
      visit(r.residual);
      visit(r.mean_contact_force);
      visit(r.iterations);
      visit(r.cg_iterations);
      visit(r.cutbacks);
      visit(r.relaxed);
      visit(r.rho_interior);
      visit(r.sigma_zz_interior);
      visit(r.sigma_rr_interior);
      visit(r.coordination_interior);
      // Not the timing (wall_seconds): the same study gives the same
      // checkpoint.
    }

    template <typename Summary, typename Visit>
    void
    for_each_summary_field(Summary &s, Visit &&visit)
    {
      visit(s.branch);
      visit(s.rho_max_in_die);
      visit(s.rho_min_in_die);
      visit(s.rho_tablet);
      visit(s.max_punch_pressure);
      visit(s.elastic_recovery_rho);
      visit(s.elastic_recovery_H);
      visit(s.residual_radial_pressure);
      visit(s.ejection_pressure);
      visit(s.bonding_surface_compacted);
      visit(s.bonding_surface_unloaded);
      visit(s.bonding_surface_ejected);
      visit(s.coordination_compacted);
      visit(s.tablet.youngs_modulus);
      visit(s.tablet.poisson_ratio);
      visit(s.tablet.n_points);
    }

    /// Appends a field to a row of doubles (exact for every integer field:
    /// counts stay far below 2^53).
    struct Pack
    {
      std::vector<double> &out;
      template <typename T>
      void
      operator()(const T &value) const
      {
        out.push_back(static_cast<double>(value));
      }
    };

    struct Unpack
    {
      const double *&in;
      template <typename T>
      void
      operator()(T &value) const
      {
        value = static_cast<T>(*in++);
      }
    };

    std::size_t
    count_fields()
    {
      dem::DieRecord      r;
      std::vector<double> v;
      for_each_field(r, Pack{v});
      return v.size() + 1;
    }

    std::size_t
    count_summary_fields()
    {
      dem::BranchSummary  s;
      std::vector<double> v;
      for_each_summary_field(s, Pack{v});
      return v.size();
    }

    /// Stores @p files under @p group of an archive.
    void
    save_branch_files(Hdf5ArchiveWriter    &archive,
                      const std::string    &group,
                      const DieBranchFiles &files)
    {
      archive.write_text(group + "/fabric_rows", files.fabric_rows);
      archive.write_text(group + "/histogram_rows", files.histogram_rows);
      std::string list;
      for (const auto &[name, hash] : files.files)
        list += hash + " " + name + "\n";
      archive.write_text(group + "/files", list);
    }

    /// Reads what save_branch_files() stored; refuses a list naming a file
    /// outside the run folder.
    DieBranchFiles
    load_branch_files(const Hdf5ArchiveReader &archive,
                      const std::string       &group)
    {
      DieBranchFiles files;
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
  } // namespace

  void
  write_die_checkpoint(const std::string      &file,
                       const std::string      &parameters,
                       const dem::Bed         &bed,
                       const dem::DieProgress &progress,
                       const DieBranchFiles   &branch_files)
  {
    write_archive(
      file,
      {archive_kind::die_compaction, parameters},
      [&](Hdf5ArchiveWriter &archive) {
        archive.write_attribute("completed_targets",
                                double(progress.completed_targets));
        archive.write_attribute("branches_run", double(progress.branches_run));
        archive.write_attribute("jamming_density", progress.jamming_density);
        archive.write_attribute("relative_density", bed.relative_density());
        archive.write_attribute("newton_iterations",
                                double(progress.work.iterations));
        archive.write_attribute("cg_iterations",
                                double(progress.work.cg_iterations));
        archive.write_attribute("assemblies", double(progress.work.assemblies));
        archive.write_attribute("fire_iterations",
                                double(progress.work.fire_iterations));
        archive.write_attribute("rows", double(progress.rows.size()));
        archive.write_attribute("branches", double(progress.branches.size()));
        save_bed(archive, "bed", bed);
        archive.write_array("compaction_targets", progress.compaction_targets);

        const std::size_t   n_fields = count_fields();
        std::vector<double> rows;
        for (const auto &r : progress.rows)
          {
            rows.push_back(stage_code(r.stage));
            for_each_field(r, Pack{rows});
          }
        archive.write_array("rows", rows, {progress.rows.size(), n_fields});

        const std::size_t   n_summary = count_summary_fields();
        std::vector<double> branches;
        for (const auto &b : progress.branches)
          for_each_summary_field(b, Pack{branches});
        archive.write_array("branches",
                            branches,
                            {progress.branches.size(), n_summary});
        save_branch_files(archive, "branch_files", branch_files);
      });
  }

  DieCheckpoint
  read_die_checkpoint(const std::string       &file,
                      const std::string       &parameters,
                      const dem::ContactModel &model)
  {
    const Hdf5ArchiveReader archive(file,
                                    archive_kind::die_compaction,
                                    parameters);
    DieCheckpoint           checkpoint;
    dem::DieProgress       &p     = checkpoint.progress;
    const auto              count = [&](const std::string &name) {
      const double v = archive.read_attribute(name);
      if (!(v >= 0.0 && v < 1e15 && v == std::floor(v)))
        throw std::runtime_error("attribute '" + name
                                 + "' is not a count (damaged)");
      return v;
    };
    p.completed_targets  = static_cast<std::size_t>(count("completed_targets"));
    p.branches_run       = static_cast<int>(count("branches_run"));
    p.jamming_density    = archive.read_attribute("jamming_density");
    p.work.iterations    = static_cast<long>(count("newton_iterations"));
    p.work.cg_iterations = static_cast<long>(count("cg_iterations"));
    p.work.assemblies    = static_cast<long>(count("assemblies"));
    p.work.fire_iterations = static_cast<long>(count("fire_iterations"));
    const auto n_rows      = static_cast<std::size_t>(count("rows"));
    const auto n_branches  = static_cast<std::size_t>(count("branches"));
    checkpoint.bed         = load_bed(archive, "bed", model);
    p.compaction_targets   = archive.read_array("compaction_targets");

    const std::size_t n_fields = count_fields();
    const auto        values   = archive.read_array("rows");
    if (values.size() != n_rows * n_fields)
      throw std::runtime_error("checkpoint rows have the wrong size");
    const double *in = values.data();
    for (std::size_t k = 0; k < n_rows; ++k)
      {
        dem::DieRecord r;
        const int      code = static_cast<int>(*in++);
        if (code < 0 || code > 2)
          throw std::runtime_error("checkpoint row with an unknown stage");
        r.stage = stages[code];
        for_each_field(r, Unpack{in});
        p.rows.push_back(r);
      }
    const std::size_t n_summary = count_summary_fields();
    const auto        summaries = archive.read_array("branches");
    if (summaries.size() != n_branches * n_summary)
      throw std::runtime_error("checkpoint branches have the wrong size");
    in = summaries.data();
    for (std::size_t k = 0; k < n_branches; ++k)
      {
        dem::BranchSummary s;
        for_each_summary_field(s, Unpack{in});
        p.branches.push_back(s);
      }
    checkpoint.branch_files = load_branch_files(archive, "branch_files");
    if (p.completed_targets > p.compaction_targets.size() || p.rows.empty()
        || p.branches_run < 0)
      throw std::runtime_error("inconsistent die checkpoint");
    return checkpoint;
  }
} // namespace compax::coupling

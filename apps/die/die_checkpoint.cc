#include "apps/die/die_checkpoint.h"

#include "apps/die/bed_checkpoint.h"

#include <stdexcept>

namespace compax::cli
{
  namespace
  {
    const char *const format = "compax die compaction checkpoint 1";

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
      visit(r.wall_seconds);
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
  } // namespace

  void
  write_die_checkpoint(const std::string      &file,
                       const dem::Bed         &bed,
                       const dem::DieProgress &progress)
  {
    coupling::Hdf5ArchiveWriter archive(file);
    archive.write_attribute("format", format);
    archive.write_attribute("completed_targets",
                            double(progress.completed_targets));
    archive.write_attribute("branches_run", double(progress.branches_run));
    archive.write_attribute("jamming_density", progress.jamming_density);
    archive.write_attribute("relative_density", bed.relative_density());
    archive.write_attribute("newton_iterations",
                            double(progress.newton_iterations));
    archive.write_attribute("cg_iterations", double(progress.cg_iterations));
    archive.write_attribute("assemblies", double(progress.assemblies));
    archive.write_attribute("fire_iterations",
                            double(progress.fire_iterations));
    archive.write_attribute("rows", double(progress.rows.size()));
    archive.write_attribute("branches", double(progress.branches.size()));
    save_bed(archive, "bed", bed);
    if (!progress.compaction_targets.empty())
      archive.write_array("compaction_targets", progress.compaction_targets);

    const std::size_t   n_fields = count_fields();
    std::vector<double> rows;
    for (const auto &r : progress.rows)
      {
        rows.push_back(stage_code(r.stage));
        for_each_field(r, Pack{rows});
      }
    if (!progress.rows.empty())
      archive.write_array("rows", rows, {progress.rows.size(), n_fields});

    const std::size_t   n_summary = count_summary_fields();
    std::vector<double> branches;
    for (const auto &b : progress.branches)
      for_each_summary_field(b, Pack{branches});
    if (!progress.branches.empty())
      archive.write_array("branches",
                          branches,
                          {progress.branches.size(), n_summary});
    archive.commit();
  }

  dem::DieProgress
  read_die_checkpoint(const std::string       &file,
                      const dem::ContactModel &model,
                      dem::Bed                &bed)
  {
    const coupling::Hdf5ArchiveReader archive(file);
    if (!archive.has_attribute("format")
        || archive.read_text_attribute("format") != format)
      throw std::runtime_error("not a compax die compaction checkpoint "
                               "(checkpoints/compaction.h5)");
    dem::DieProgress p;
    p.completed_targets
      = static_cast<std::size_t>(archive.read_attribute("completed_targets"));
    p.branches_run = static_cast<int>(archive.read_attribute("branches_run"));
    p.jamming_density = archive.read_attribute("jamming_density");
    p.newton_iterations
      = static_cast<long>(archive.read_attribute("newton_iterations"));
    p.cg_iterations
      = static_cast<long>(archive.read_attribute("cg_iterations"));
    p.assemblies = static_cast<long>(archive.read_attribute("assemblies"));
    p.fire_iterations
      = static_cast<long>(archive.read_attribute("fire_iterations"));
    const auto n_rows
      = static_cast<std::size_t>(archive.read_attribute("rows"));
    const auto n_branches
      = static_cast<std::size_t>(archive.read_attribute("branches"));
    bed = load_bed(archive, "bed", model);
    if (archive.has_array("compaction_targets"))
      p.compaction_targets = archive.read_array("compaction_targets");

    if (n_rows > 0)
      {
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
      }
    if (n_branches > 0)
      {
        const std::size_t n_summary = count_summary_fields();
        const auto        values    = archive.read_array("branches");
        if (values.size() != n_branches * n_summary)
          throw std::runtime_error("checkpoint branches have the wrong size");
        const double *in = values.data();
        for (std::size_t k = 0; k < n_branches; ++k)
          {
            dem::BranchSummary s;
            for_each_summary_field(s, Unpack{in});
            p.branches.push_back(s);
          }
      }
    if (p.completed_targets > p.compaction_targets.size() || p.rows.empty())
      throw std::runtime_error("inconsistent die checkpoint");
    return p;
  }
} // namespace compax::cli

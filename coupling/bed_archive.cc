#include "coupling/bed_archive.h"

#include "coupling/history_columns.h"
#include "coupling/particle_archive.h"

#include <algorithm>
#include <stdexcept>

namespace compax::coupling
{
  namespace
  {
    /// Key (two columns), then the internal variables (history_columns.h).
    constexpr hsize_t row_columns = 2 + history_columns;

    /// Columns of a saved history table (row_columns, or the legacy
    /// layouts history_from_columns() reads).
    std::size_t
    columns_of(const Hdf5ArchiveReader &archive, const std::string &name)
    {
      const std::vector<hsize_t> shape = archive.array_shape(name);
      const std::size_t columns = shape.size() == 2 ? shape[1] : row_columns;
      if (columns < 2)
        throw std::runtime_error("checkpoint array '" + name + "' has "
                                 + std::to_string(columns) + " columns");
      return columns;
    }
  } // namespace

  void
  save_bed(Hdf5ArchiveWriter &archive,
           const std::string &group,
           const dem::Bed    &bed)
  {
    save_particles(archive, group, bed.particles);
    archive.write_array(group + "/walls",
                        {bed.walls.diameter,
                         bed.walls.lower_punch,
                         bed.walls.upper_punch,
                         bed.walls.die_present ? 1.0 : 0.0,
                         bed.contacts.skin()});

    // Columns: the contact's key (i, j) or (i, wall), then its internal
    // variables.
    std::vector<double> pairs, walls;
    bed.contacts.for_each_kept_pair([&](const dem::PairContact &c) {
      if (dem::has_history(c.history))
        {
          pairs.insert(pairs.end(), {double(c.i), double(c.j)});
          append_history(pairs, c.history);
        }
    });
    for (const auto &c : bed.contacts.walls)
      if (dem::has_history(c.history))
        {
          walls.insert(walls.end(),
                       {double(c.i), double(static_cast<int>(c.wall))});
          append_history(walls, c.history);
        }
    archive.write_array(group + "/pair_histories",
                        pairs,
                        {pairs.size() / row_columns, row_columns});
    archive.write_array(group + "/wall_histories",
                        walls,
                        {walls.size() / row_columns, row_columns});
  }

  dem::Bed
  load_bed(const Hdf5ArchiveReader &archive,
           const std::string       &group,
           const dem::ContactModel &model)
  {
    dem::Bed bed;
    bed.particles = load_particles(archive,
                                   group,
                                   model,
                                   "checkpoint group '" + group + "'",
                                   "a particle's material or radius is not "
                                   "one of this contact model");

    const auto walls      = archive.read_array(group + "/walls");
    bed.walls.diameter    = walls.at(0);
    bed.walls.lower_punch = walls.at(1);
    bed.walls.upper_punch = walls.at(2);
    bed.walls.die_present = walls.at(3) != 0.0;
    bed.contacts.set_skin(walls.at(4));

    // Saved histories become the "old" contacts that a rebuild merges with
    // the candidates (both sorted by (i, j) and by (i, wall)).
    const auto &p     = bed.particles;
    const auto  h     = archive.read_array(group + "/pair_histories");
    const auto  index = [&](double v) {
      if (!(v >= 0 && v < double(p.size())))
        throw std::runtime_error("checkpoint group '" + group
                                 + "': a contact's particle index is out of "
                                    "range");
      return static_cast<std::uint32_t>(v);
    };
    const std::size_t hc = columns_of(archive, group + "/pair_histories");
    for (std::size_t k = 0; k + hc <= h.size(); k += hc)
      {
        const auto             i   = index(h[k]);
        const auto             j   = index(h[k + 1]);
        const dem::ParticleLaw law = model.pair_law(p.materials[i],
                                                    p.radii[i],
                                                    p.materials[j],
                                                    p.radii[j]);
        bed.contacts.pairs.push_back(
          {i, j, law, history_from_columns(&h[k + 2], hc - 2, law)});
      }
    // Active and dormant pairs were saved one list after the other.
    std::sort(bed.contacts.pairs.begin(),
              bed.contacts.pairs.end(),
              [](const dem::PairContact &a, const dem::PairContact &b) {
                return dem::pair_key(a) < dem::pair_key(b);
              });
    const auto        w  = archive.read_array(group + "/wall_histories");
    const std::size_t wc = columns_of(archive, group + "/wall_histories");
    for (std::size_t k = 0; k + wc <= w.size(); k += wc)
      {
        const auto i = index(w[k]);
        if (!(w[k + 1] >= 0 && w[k + 1] <= 2))
          throw std::runtime_error("checkpoint group '" + group
                                   + "': unknown wall");
        const dem::ParticleLaw law = model.wall_law(p.materials[i], p.radii[i]);
        bed.contacts.walls.push_back(
          {i,
           static_cast<dem::Wall>(static_cast<int>(w[k + 1])),
           law,
           history_from_columns(&w[k + 2], wc - 2, law)});
      }
    bed.contacts.rebuild(bed.particles, bed.walls, model);
    return bed;
  }
} // namespace compax::coupling

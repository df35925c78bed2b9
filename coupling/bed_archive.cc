#include "coupling/bed_archive.h"

#include <stdexcept>

namespace compax::coupling
{
  void
  save_bed(Hdf5ArchiveWriter &archive,
           const std::string &group,
           const dem::Bed    &bed)
  {
    const auto         &p = bed.particles;
    std::vector<double> x, radii(p.radii), materials;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        x.insert(x.end(), p.positions[i].data(), p.positions[i].data() + 3);
        materials.push_back(p.materials[i]);
      }
    archive.write_array(group + "/positions", x, {p.size(), 3});
    archive.write_array(group + "/radii", radii);
    archive.write_array(group + "/materials", materials);
    archive.write_array(group + "/walls",
                        {bed.walls.diameter,
                         bed.walls.lower_punch,
                         bed.walls.upper_punch,
                         bed.walls.die_present ? 1.0 : 0.0,
                         bed.contacts.skin()});

    std::vector<double> pairs, walls;
    for (const auto &c : bed.contacts.pairs)
      if (c.history.a_p > 0 || c.history.a_B > 0)
        pairs.insert(pairs.end(),
                     {double(c.i), double(c.j), c.history.a_p, c.history.a_B});
    for (const auto &c : bed.contacts.walls)
      if (c.history.a_p > 0 || c.history.a_B > 0)
        walls.insert(walls.end(),
                     {double(c.i),
                      double(static_cast<int>(c.wall)),
                      c.history.a_p,
                      c.history.a_B});
    archive.write_array(group + "/pair_histories",
                        pairs,
                        {pairs.size() / 4, 4});
    archive.write_array(group + "/wall_histories",
                        walls,
                        {walls.size() / 4, 4});
  }

  dem::Bed
  load_bed(const Hdf5ArchiveReader &archive,
           const std::string       &group,
           const dem::ContactModel &model)
  {
    dem::Bed   bed;
    const auto x         = archive.read_array(group + "/positions");
    const auto radii     = archive.read_array(group + "/radii");
    const auto materials = archive.read_array(group + "/materials");
    if (x.size() != 3 * radii.size() || materials.size() != radii.size())
      throw std::runtime_error("checkpoint group '" + group
                               + "': inconsistent particle arrays");
    for (std::size_t i = 0; i < radii.size(); ++i)
      {
        if (!(materials[i] >= 0 && materials[i] < model.n_materials())
            || !(radii[i] > 0))
          throw std::runtime_error("checkpoint group '" + group
                                   + "': a particle's material or radius is "
                                     "not one of this contact model");
        bed.particles.add({x[3 * i], x[3 * i + 1], x[3 * i + 2]},
                          radii[i],
                          static_cast<unsigned int>(materials[i]));
      }
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
    for (std::size_t k = 0; k + 3 < h.size(); k += 4)
      {
        const auto i = index(h[k]);
        const auto j = index(h[k + 1]);
        bed.contacts.pairs.push_back(
          {i,
           j,
           model.pair_law(
             p.materials[i], p.radii[i], p.materials[j], p.radii[j]),
           dem::ContactHistory{h[k + 2], h[k + 3], 0.0}});
      }
    const auto w = archive.read_array(group + "/wall_histories");
    for (std::size_t k = 0; k + 3 < w.size(); k += 4)
      {
        const auto i = index(w[k]);
        if (!(w[k + 1] >= 0 && w[k + 1] <= 2))
          throw std::runtime_error("checkpoint group '" + group
                                   + "': unknown wall");
        bed.contacts.walls.push_back(
          {i,
           static_cast<dem::Wall>(static_cast<int>(w[k + 1])),
           model.wall_law(p.materials[i], p.radii[i]),
           dem::ContactHistory{w[k + 2], w[k + 3], 0.0}});
      }
    bed.contacts.rebuild(bed.particles, bed.walls, model);
    return bed;
  }
} // namespace compax::coupling

#include "coupling/particle_archive.h"

#include <stdexcept>

namespace compax::coupling
{
  void
  save_particles(Hdf5ArchiveWriter         &archive,
                 const std::string         &group,
                 const dem::ParticleSystem &particles)
  {
    const auto         &p = particles;
    std::vector<double> x, materials;
    x.reserve(3 * p.size());
    materials.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        x.insert(x.end(), p.positions[i].data(), p.positions[i].data() + 3);
        materials.push_back(p.materials[i]);
      }
    archive.write_array(group + "/positions", x, {p.size(), 3});
    archive.write_array(group + "/radii", p.radii);
    archive.write_array(group + "/materials", materials);
  }

  dem::ParticleSystem
  load_particles(const Hdf5ArchiveReader &archive,
                 const std::string       &group,
                 const dem::ContactModel &model,
                 const std::string       &where,
                 const std::string       &foreign_particle)
  {
    dem::ParticleSystem particles;
    const auto          x         = archive.read_array(group + "/positions");
    const auto          radii     = archive.read_array(group + "/radii");
    const auto          materials = archive.read_array(group + "/materials");
    if (x.size() != 3 * radii.size() || materials.size() != radii.size())
      throw std::runtime_error(where + ": inconsistent particle arrays");
    for (std::size_t i = 0; i < radii.size(); ++i)
      {
        if (!(materials[i] >= 0 && materials[i] < model.n_materials())
            || !(radii[i] > 0))
          throw std::runtime_error(where + ": " + foreign_particle);
        particles.add({x[3 * i], x[3 * i + 1], x[3 * i + 2]},
                      radii[i],
                      static_cast<unsigned int>(materials[i]));
      }
    return particles;
  }
} // namespace compax::coupling

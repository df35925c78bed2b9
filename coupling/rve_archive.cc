#include "coupling/rve_archive.h"

#include "coupling/history_columns.h"
#include "coupling/particle_archive.h"

#include <cmath>
#include <stdexcept>

namespace compax::coupling
{
  namespace
  {
    /// Row-major 3x3 matrix as 9 doubles.
    std::vector<double>
    flatten(const Eigen::Matrix3d &A)
    {
      std::vector<double> v(9);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          v[3 * r + c] = A(r, c);
      return v;
    }

    Eigen::Matrix3d
    unflatten(const std::vector<double> &v, const std::string &name)
    {
      if (v.size() != 9)
        throw std::runtime_error("RVE archive entry '" + name
                                 + "': expected 9 values");
      Eigen::Matrix3d A;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          A(r, c) = v[3 * r + c];
      return A;
    }

    /// i, j, the lattice image (3), then the internal variables.
    constexpr std::size_t key_columns     = 5;
    constexpr std::size_t contact_columns = key_columns + history_columns;
  } // namespace

  void
  save_rve(Hdf5ArchiveWriter      &archive,
           const std::string      &group,
           const dem::PeriodicBed &bed)
  {
    save_particles(archive, group, bed.particles);
    archive.write_array(group + "/lattice",
                        flatten(bed.cell.lattice()),
                        {3, 3});
    archive.write_array(group + "/reference_lattice",
                        flatten(bed.reference_lattice),
                        {3, 3});
    archive.write_array(group + "/deformation",
                        flatten(bed.deformation),
                        {3, 3});
    archive.write_array(group + "/periodic",
                        {bed.cell.periodic(0) ? 1.0 : 0.0,
                         bed.cell.periodic(1) ? 1.0 : 0.0,
                         bed.cell.periodic(2) ? 1.0 : 0.0});
    archive.write_array(group + "/skin", {bed.contacts.skin()});

    std::vector<double> contacts;
    contacts.reserve(contact_columns * bed.contacts.pairs.size());
    for (const dem::PeriodicContact &c : bed.contacts.pairs)
      {
        contacts.insert(contacts.end(),
                        {double(c.i),
                         double(c.j),
                         double(c.image[0]),
                         double(c.image[1]),
                         double(c.image[2])});
        append_history(contacts, c.history);
      }
    archive.write_array(group + "/contacts",
                        contacts,
                        {bed.contacts.pairs.size(), contact_columns});
  }

  dem::PeriodicBed
  load_rve(const Hdf5ArchiveReader &archive,
           const std::string       &group,
           const dem::ContactModel &model)
  {
    dem::PeriodicBed bed;
    bed.particles = load_particles(archive,
                                   group,
                                   model,
                                   "RVE archive group '" + group + "'",
                                   "a particle's material or radius is not "
                                   "one of the contact model");

    const auto periodic = archive.read_array(group + "/periodic");
    if (periodic.size() != 3)
      throw std::runtime_error("RVE archive group '" + group
                               + "': expected 3 periodicity flags");
    bed.cell = dem::PeriodicCell(
      unflatten(archive.read_array(group + "/lattice"), group + "/lattice"),
      {periodic[0] != 0.0, periodic[1] != 0.0, periodic[2] != 0.0});
    bed.reference_lattice
      = unflatten(archive.read_array(group + "/reference_lattice"),
                  group + "/reference_lattice");
    bed.deformation = unflatten(archive.read_array(group + "/deformation"),
                                group + "/deformation");
    const auto skin = archive.read_array(group + "/skin");
    if (skin.size() != 1)
      throw std::runtime_error("RVE archive group '" + group
                               + "': expected one skin value");
    bed.contacts.set_skin(skin[0]);

    const auto        c = archive.read_array(group + "/contacts");
    const std::size_t n = bed.particles.size();
    // Archives written before the laws declared their variables hold
    // eight columns (history_columns.h).
    const std::vector<hsize_t> shape = archive.array_shape(group + "/contacts");
    const std::size_t columns = shape.size() == 2 ? shape[1] : contact_columns;
    if (columns <= key_columns || c.size() % columns != 0)
      throw std::runtime_error("RVE archive group '" + group
                               + "': malformed contact table");
    const auto &p = bed.particles;
    bed.contacts.pairs.reserve(c.size() / columns);
    for (std::size_t k = 0; k < c.size(); k += columns)
      {
        if (!(c[k] >= 0 && c[k] < double(n) && c[k + 1] >= 0
              && c[k + 1] < double(n)))
          throw std::runtime_error("RVE archive group '" + group
                                   + "': contact with a particle index out "
                                     "of range");
        for (int d = 2; d < 5; ++d)
          if (!(std::abs(c[k + d]) < 1e6))
            throw std::runtime_error("RVE archive group '" + group
                                     + "': contact with an invalid image");
        const auto              i = static_cast<std::uint32_t>(c[k]);
        const auto              j = static_cast<std::uint32_t>(c[k + 1]);
        const dem::LatticeImage image{static_cast<std::int32_t>(c[k + 2]),
                                      static_cast<std::int32_t>(c[k + 3]),
                                      static_cast<std::int32_t>(c[k + 4])};
        const dem::ParticleLaw  law = model.pair_law(p.materials[i],
                                                    p.radii[i],
                                                    p.materials[j],
                                                    p.radii[j]);
        bed.contacts.pairs.push_back(
          {i,
           j,
           image,
           law,
           history_from_columns(&c[k + key_columns],
                                columns - key_columns,
                                law)});
      }
    bed.contacts.rebuild(bed.particles, bed.cell, model);
    return bed;
  }

  void
  save_rve(const std::string      &path,
           const dem::PeriodicBed &bed,
           const std::string      &parameters)
  {
    write_archive(path,
                  {archive_kind::rve_state, parameters},
                  [&](Hdf5ArchiveWriter &archive) {
                    save_rve(archive, "rve", bed);
                  });
  }

  dem::PeriodicBed
  load_rve(const std::string                &path,
           const dem::ContactModel          &model,
           const std::optional<std::string> &parameters)
  {
    const Hdf5ArchiveReader archive(path, archive_kind::rve_state, parameters);
    try
      {
        return load_rve(archive, "rve", model);
      }
    catch (const Hdf5ArchiveError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        throw Hdf5ArchiveError(path, e.what());
      }
  }
} // namespace compax::coupling

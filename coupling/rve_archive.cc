#include "coupling/rve_archive.h"

#include <stdexcept>

namespace compax::coupling
{
  namespace
  {
    constexpr const char *format_tag = "compax rve state 1";

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

    constexpr std::size_t contact_columns = 8;
  } // namespace

  void
  save_rve(Hdf5ArchiveWriter      &archive,
           const std::string      &group,
           const dem::PeriodicBed &bed)
  {
    const auto         &p = bed.particles;
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
      contacts.insert(contacts.end(),
                      {double(c.i),
                       double(c.j),
                       double(c.image[0]),
                       double(c.image[1]),
                       double(c.image[2]),
                       c.history.a_p,
                       c.history.a_B,
                       c.history.delta_max});
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
    const auto       x         = archive.read_array(group + "/positions");
    const auto       radii     = archive.read_array(group + "/radii");
    const auto       materials = archive.read_array(group + "/materials");
    if (x.size() != 3 * radii.size() || materials.size() != radii.size())
      throw std::runtime_error("RVE archive group '" + group
                               + "': inconsistent particle arrays");
    for (std::size_t i = 0; i < radii.size(); ++i)
      {
        const auto m = static_cast<unsigned int>(materials[i]);
        if (m >= model.n_materials())
          throw std::runtime_error(
            "RVE archive group '" + group + "': particle material "
            + std::to_string(m + 1) + " is not in the contact model");
        bed.particles.add({x[3 * i], x[3 * i + 1], x[3 * i + 2]}, radii[i], m);
      }
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
    const std::size_t n = radii.size();
    if (c.size() % contact_columns != 0)
      throw std::runtime_error("RVE archive group '" + group
                               + "': malformed contact table");
    const auto &p = bed.particles;
    bed.contacts.pairs.reserve(c.size() / contact_columns);
    for (std::size_t k = 0; k < c.size(); k += contact_columns)
      {
        const auto i = static_cast<std::uint32_t>(c[k]);
        const auto j = static_cast<std::uint32_t>(c[k + 1]);
        if (i >= n || j >= n)
          throw std::runtime_error("RVE archive group '" + group
                                   + "': contact with a particle index out "
                                     "of range");
        const dem::LatticeImage image{static_cast<std::int32_t>(c[k + 2]),
                                      static_cast<std::int32_t>(c[k + 3]),
                                      static_cast<std::int32_t>(c[k + 4])};
        bed.contacts.pairs.push_back(
          {i,
           j,
           image,
           model.pair_law(
             p.materials[i], p.radii[i], p.materials[j], p.radii[j]),
           dem::ContactHistory{c[k + 5], c[k + 6], c[k + 7]}});
      }
    bed.contacts.rebuild(bed.particles, bed.cell, model);
    return bed;
  }

  void
  save_rve(const std::string &path, const dem::PeriodicBed &bed)
  {
    Hdf5ArchiveWriter archive(path);
    archive.write_attribute("format", format_tag);
    save_rve(archive, "rve", bed);
    archive.commit();
  }

  dem::PeriodicBed
  load_rve(const std::string &path, const dem::ContactModel &model)
  {
    // An exception must not unwind through an open HDF5 file (deal.II
    // aborts then): errors are collected and thrown after it is closed.
    dem::PeriodicBed bed;
    std::string      error;
    {
      const Hdf5ArchiveReader archive(path);
      try
        {
          if (!archive.has_attribute("format")
              || archive.read_text_attribute("format") != format_tag)
            error = "'" + path + "' is not a compax RVE archive";
          else
            bed = load_rve(archive, "rve", model);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    }
    if (!error.empty())
      throw Hdf5ArchiveError(error);
    return bed;
  }
} // namespace compax::coupling

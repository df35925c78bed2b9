#include "dem/io/particle_vtu.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    template <typename T>
    void
    write_array(std::ofstream        &out,
                const char           *name,
                const char           *type,
                const std::vector<T> &values)
    {
      out << "        <DataArray type=\"" << type << "\" Name=\"" << name
          << "\" format=\"ascii\">\n         ";
      for (const T &v : values)
        out << ' ' << v;
      out << "\n        </DataArray>\n";
    }
  } // namespace

  ParticleSnapshot::ParticleSnapshot(const ParticleSystem &p)
      : points(p.positions)
      , radii(p.radii)
      , material(p.materials.begin(), p.materials.end())
      , coordination(p.size(), 0)
      , bonds(p.size(), 0)
      , plastic_radius(p.size(), 0.0)
      , force_sum(p.size(), 0.0)
      , net(p.size(), Eigen::Vector3d::Zero())
  {
  }

  void
  ParticleSnapshot::add_contact(const std::uint32_t    i,
                                const std::uint32_t    j,
                                const Eigen::Vector3d &n,
                                const double           P,
                                const ContactHistory  &h)
  {
    for (const auto k : {i, j})
      {
        plastic_radius[k] = std::max(plastic_radius[k], h.a_p);
        bonds[k] += h.a_B > 0.0;
      }
    if (P == 0.0)
      return;
    net[i] += P * n;
    net[j] -= P * n;
    for (const auto k : {i, j})
      {
        ++coordination[k];
        force_sum[k] += P;
      }
  }

  void
  ParticleSnapshot::write(const std::filesystem::path &file) const
  {
    const std::size_t   n = points.size();
    std::vector<double> net_force(n), mean_force(n);
    for (std::size_t k = 0; k < n; ++k)
      {
        net_force[k]  = net[k].norm();
        mean_force[k] = coordination[k] ? force_sum[k] / coordination[k] : 0;
      }
    std::ofstream out(file);
    if (!out)
      throw std::runtime_error("cannot write '" + file.string() + "'");
    out.precision(10);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n
        << "\">\n      <Points>\n        <DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto &x : points)
      out << "          " << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
    out << "        </DataArray>\n      </Points>\n      <Cells>\n";
    std::vector<std::size_t> connectivity(n), offsets(n);
    std::vector<int>         types(n, 1); // VTK_VERTEX
    for (std::size_t k = 0; k < n; ++k)
      {
        connectivity[k] = k;
        offsets[k]      = k + 1;
      }
    write_array(out, "connectivity", "Int64", connectivity);
    write_array(out, "offsets", "Int64", offsets);
    write_array(out, "types", "UInt8", types);
    out << "      </Cells>\n      <PointData Scalars=\"radius\">\n";
    write_array(out, "radius", "Float64", radii);
    write_array(out, "material", "Int32", material);
    write_array(out, "coordination", "Int32", coordination);
    write_array(out, "net_force", "Float64", net_force);
    write_array(out, "mean_contact_force", "Float64", mean_force);
    write_array(out, "max_plastic_radius", "Float64", plastic_radius);
    write_array(out, "bonds", "Int32", bonds);
    out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
  }

  void
  write_particles_vtu(const std::filesystem::path &file, const Bed &bed)
  {
    const ParticleSystem &p = bed.particles;
    ParticleSnapshot      snapshot(p);
    for (const PairContact &c : bed.contacts.pairs)
      snapshot.add_contact(
        c.i,
        c.j,
        (p.positions[c.i] - p.positions[c.j]).normalized(),
        law_response(c.law, pair_overlap(p, c), c.history).force,
        c.history);
    snapshot.write(file);
  }

  void
  write_pvd(const std::filesystem::path                       &file,
            const std::vector<std::pair<double, std::string>> &snapshots)
  {
    const auto    partial = file.string() + ".tmp";
    std::ofstream out(partial);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
           "version=\"0.1\">\n  <Collection>\n";
    for (const auto &[time, name] : snapshots)
      out << "    <DataSet timestep=\"" << time << "\" file=\"" << name
          << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
    out.close();
    std::filesystem::rename(partial, file);
  }
} // namespace compax::dem

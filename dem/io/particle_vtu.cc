#include "dem/io/particle_vtu.h"

#include <algorithm>
#include <cstring>
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
      , force_sum(p.size(), 0.0)
      , net(p.size(), Eigen::Vector3d::Zero())
  {
  }

  void
  ParticleSnapshot::add_contact(const std::uint32_t    i,
                                const std::uint32_t    j,
                                const Eigen::Vector3d &n,
                                const double           P,
                                const ParticleLaw     &law,
                                const ContactHistory  &h)
  {
    const std::vector<HistoryVariable> variables = history_variables(law);
    for (std::size_t v = 0; v < variables.size(); ++v)
      {
        const char *name = variables[v].name;
        auto        it   = std::find_if(largest_history.begin(),
                               largest_history.end(),
                               [&](const auto &a) {
                                 return std::strcmp(a.first, name) == 0;
                               });
        if (it == largest_history.end())
          it = largest_history.insert(
            it, {name, std::vector<double>(points.size(), 0.0)});
        for (const auto k : {i, j})
          it->second[k] = std::max(it->second[k], h[v]);
      }
    const bool bridge = bonded(law, h);
    for (const auto k : {i, j})
      bonds[k] += bridge;
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
    for (const auto &[name, largest] : largest_history)
      write_array(out,
                  ("max_" + std::string(name)).c_str(),
                  "Float64",
                  largest);
    write_array(out, "bonds", "Int32", bonds);
    out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
  }

  void
  write_particles_vtu(const std::filesystem::path &file, const Bed &bed)
  {
    const ParticleSystem &p = bed.particles;
    ParticleSnapshot      snapshot(p);
    bed.contacts.for_each_kept_pair([&](const PairContact &c) {
      snapshot.add_contact(
        c.i,
        c.j,
        (p.positions[c.i] - p.positions[c.j]).normalized(),
        law_response(c.law, pair_overlap(p, c), c.history).force,
        c.law,
        c.history);
    });
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

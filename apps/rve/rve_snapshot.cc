#include "apps/rve/rve_snapshot.h"

#include "dem/rve/periodic_assembler.h"

#include <fstream>
#include <stdexcept>
#include <vector>

namespace compax::cli
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

  void
  write_rve_vtu(const std::filesystem::path &file, const dem::PeriodicBed &bed)
  {
    const auto                  &p = bed.particles;
    const std::size_t            n = p.size();
    std::vector<int>             coordination(n, 0), bonds(n, 0);
    std::vector<double>          plastic_radius(n, 0.0), force_sum(n, 0.0);
    std::vector<Eigen::Vector3d> net(n, Eigen::Vector3d::Zero());
    for (const dem::PeriodicContact &c : bed.contacts.pairs)
      {
        for (const auto k : {c.i, c.j})
          {
            plastic_radius[k] = std::max(plastic_radius[k], c.history.a_p);
            bonds[k] += c.history.a_B > 0.0;
          }
        const Eigen::Vector3d d     = dem::branch_vector(p, bed.cell, c);
        const double          gamma = p.radii[c.i] + p.radii[c.j] - d.norm();
        if (c.history.a_p == 0.0 && gamma <= 0.0)
          continue;
        const double P
          = dem::periodic_contact_response(c,
                                           gamma,
                                           dem::ContactBranch::current)
              .force;
        if (P == 0.0)
          continue;
        const Eigen::Vector3d n_ij = d.normalized();
        net[c.i] += P * n_ij;
        net[c.j] -= P * n_ij;
        for (const auto k : {c.i, c.j})
          {
            ++coordination[k];
            force_sum[k] += P;
          }
      }
    std::vector<double> net_force(n), mean_force(n);
    for (std::size_t k = 0; k < n; ++k)
      {
        net_force[k]  = net[k].norm();
        mean_force[k] = coordination[k] ? force_sum[k] / coordination[k] : 0;
      }
    std::vector<int> material(p.materials.begin(), p.materials.end());

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
    for (Eigen::Vector3d x : p.positions)
      {
        bed.cell.wrap(x);
        out << "          " << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
      }
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
    write_array(out, "radius", "Float64", p.radii);
    write_array(out, "material", "Int32", material);
    write_array(out, "coordination", "Int32", coordination);
    write_array(out, "net_force", "Float64", net_force);
    write_array(out, "mean_contact_force", "Float64", mean_force);
    write_array(out, "max_plastic_radius", "Float64", plastic_radius);
    write_array(out, "bonds", "Int32", bonds);
    out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
  }
} // namespace compax::cli

#include "coupling/rve_database_archive.h"

#include "coupling/rve_archive.h"
#include "dem/rve/homogenization.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace compax::coupling
{
  void
  write_database(Hdf5ArchiveWriter &h5, const RveDatabase &db)
  {
    h5.write_attribute("units", "stress Pa, density and strain 1");
    // Path names: rows/path holds an index into path_names.
    std::vector<std::string> names;
    std::vector<double> branch, path, parent, density, shear, strain, stress,
      deformation;
    for (const DatabaseRow &r : db.rows)
      {
        auto it = std::find(names.begin(), names.end(), r.path);
        if (it == names.end())
          it = names.insert(names.end(), r.path);
        branch.push_back(r.branch);
        path.push_back(static_cast<double>(it - names.begin()));
        parent.push_back(r.parent);
        density.push_back(r.relative_density);
        shear.push_back(r.shear_strain);
        const dem::Vector6d eps
          = dem::to_voigt(dem::logarithmic_strain(r.deformation));
        for (int k = 0; k < 6; ++k)
          {
            strain.push_back(eps[k]);
            stress.push_back(r.stress[k]);
          }
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            deformation.push_back(r.deformation(i, j));
      }
    std::string joined;
    for (const std::string &n : names)
      joined += (joined.empty() ? "" : ",") + n;
    h5.write_attribute("path_names", joined);
    const std::size_t n = db.rows.size();
    h5.write_array("rows/branch", branch);
    h5.write_array("rows/path", path);
    h5.write_array("rows/parent", parent);
    h5.write_array("rows/relative_density", density);
    h5.write_array("rows/shear_strain", shear);
    h5.write_array("rows/strain", strain, {n, 6});
    h5.write_array("rows/stress", stress, {n, 6});
    h5.write_array("rows/deformation", deformation, {n, 9});
    h5.write_attribute("rows_columns",
                       "strain and stress: xx, yy, zz, yz, xz, xy "
                       "(logarithmic strain of the deformation gradient F, "
                       "Love-Weber Cauchy stress, tension positive); "
                       "deformation: F row-major; parent: the row a state "
                       "was reached from");
    std::vector<double> b, loaded;
    for (const DatabaseBranch &br : db.branches)
      {
        b.insert(b.end(),
                 {br.relative_density,
                  br.unloaded_density,
                  br.elastic.youngs_modulus,
                  br.elastic.poisson_ratio,
                  br.shear_failure.p,
                  br.shear_failure.q,
                  br.confined_shear_failure.p,
                  br.confined_shear_failure.q,
                  br.elastic.bulk_modulus,
                  br.elastic.shear_modulus});
        for (int k = 0; k < 6; ++k)
          loaded.push_back(br.loaded_stress[k]);
      }
    h5.write_array("branches", b, {db.branches.size(), 10});
    h5.write_array("branches_loaded_stress", loaded, {db.branches.size(), 6});
    h5.write_attribute("branches_columns",
                       "relative_density, unloaded_density, E, nu, "
                       "shear_p, shear_q, confined_shear_p, "
                       "confined_shear_q, K, G");
  }

  RveDatabase
  read_database(const Hdf5ArchiveReader &h5)
  {
    RveDatabase              db;
    std::vector<std::string> names;
    {
      std::stringstream list(h5.read_text_attribute("path_names"));
      std::string       name;
      while (std::getline(list, name, ','))
        names.push_back(name);
    }
    const auto        branch      = h5.read_array("rows/branch");
    const auto        path        = h5.read_array("rows/path");
    const auto        parent      = h5.read_array("rows/parent");
    const auto        density     = h5.read_array("rows/relative_density");
    const auto        shear       = h5.read_array("rows/shear_strain");
    const auto        stress      = h5.read_array("rows/stress");
    const auto        deformation = h5.read_array("rows/deformation");
    const std::size_t n           = branch.size();
    if (path.size() != n || parent.size() != n || density.size() != n
        || shear.size() != n || stress.size() != 6 * n
        || deformation.size() != 9 * n)
      throw std::runtime_error("the rows arrays differ in length");
    for (std::size_t r = 0; r < n; ++r)
      {
        const auto k = static_cast<std::size_t>(path[r]);
        if (!(path[r] >= 0) || k >= names.size())
          throw std::runtime_error("row path index out of range");
        DatabaseRow row{static_cast<int>(branch[r]),
                        names[k],
                        density[r],
                        shear[r],
                        dem::Vector6d::Zero()};
        for (int c = 0; c < 6; ++c)
          row.stress[c] = stress[6 * r + c];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            row.deformation(i, j) = deformation[9 * r + 3 * i + j];
        row.parent = static_cast<int>(parent[r]);
        db.rows.push_back(row);
      }
    const auto b      = h5.read_array("branches");
    const auto loaded = h5.read_array("branches_loaded_stress");
    if (b.size() % 10 != 0 || loaded.size() != b.size() / 10 * 6)
      throw std::runtime_error("the branches arrays differ in length");
    for (std::size_t k = 0; k < b.size() / 10; ++k)
      {
        const double  *v = &b[10 * k];
        DatabaseBranch br;
        br.relative_density       = v[0];
        br.unloaded_density       = v[1];
        br.elastic.youngs_modulus = v[2];
        br.elastic.poisson_ratio  = v[3];
        br.shear_failure          = {v[4], v[5]};
        br.confined_shear_failure = {v[6], v[7]};
        br.elastic.bulk_modulus   = v[8];
        br.elastic.shear_modulus  = v[9];
        for (int c = 0; c < 6; ++c)
          br.loaded_stress[c] = loaded[6 * k + c];
        db.branches.push_back(br);
      }
    return db;
  }

  void
  write_database_archive(const std::filesystem::path &file,
                         const RveDatabase           &db,
                         const std::string           &parameters)
  {
    write_archive(file.string(),
                  {archive_kind::rve_database, parameters},
                  [&](Hdf5ArchiveWriter &h5) { write_database(h5, db); });
  }

  void
  write_database_checkpoint(const std::filesystem::path &file,
                            const std::string           &parameters,
                            const RveDatabase           &db,
                            const dem::PeriodicBed      &bed)
  {
    std::filesystem::create_directories(file.parent_path());
    write_archive(file.string(),
                  {archive_kind::database_checkpoint, parameters},
                  [&](Hdf5ArchiveWriter &h5) {
                    write_database(h5, db);
                    save_rve(h5, "rve", bed);
                  });
  }

  DatabaseResume
  read_database_checkpoint(const std::string       &file,
                           const std::string       &parameters,
                           const dem::ContactModel &model)
  {
    const Hdf5ArchiveReader h5(file,
                               archive_kind::database_checkpoint,
                               parameters);
    DatabaseResume          r;
    r.database = read_database(h5);
    r.bed      = load_rve(h5, "rve", model);
    return r;
  }
} // namespace compax::coupling

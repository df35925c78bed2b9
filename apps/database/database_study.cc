#include "apps/database/database_study.h"

#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/common/gnuplot.h"
#include "apps/common/voigt_columns.h"
#include "coupling/hdf5_archive.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/rve_loading.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include <deal.II/base/utilities.h>

namespace compax::cli
{
  void
  declare_database_paths(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Paths");
    declare_quantity(prm,
                     "Final relative density",
                     "0.85",
                     open(0.0, 1.0),
                     "-",
                     "Uniaxial compaction stops here.");
    declare_quantity(prm,
                     "Compaction strain step",
                     "0.01",
                     open(0.0, 0.1),
                     "-",
                     "Axial logarithmic strain per compaction step.");
    prm.declare_entry("Branch densities",
                      "0.70, 0.75, 0.80, 0.85",
                      dealii::Patterns::List(dealii::Patterns::Double(0, 1), 2),
                      "Relative densities [-] at which the path "
                      "branches into unloading and shear probes: "
                      "increasing, above the initial and at most the "
                      "final density; one DPC table row each.");
    declare_quantity(prm,
                     "Shear strain",
                     "0.04",
                     open(0.0, 0.5),
                     "-",
                     "Engineering shear strain gamma_xz of each probe.");
    prm.declare_entry("Shear steps",
                      "20",
                      dealii::Patterns::Integer(2, 10000),
                      "Steps of each shear probe, in [2, 1e4]; the "
                      "second half gives the failure state.");
    declare_quantity(prm,
                     "Confinement strain",
                     "0.004",
                     open(0.0, 0.1),
                     "-",
                     "Volumetric compression before the second shear "
                     "probe.");
    prm.declare_entry("Radial strain ratios",
                      "-0.5, 0.5, 1.0",
                      dealii::Patterns::List(dealii::Patterns::Double(-0.5, 1),
                                             0),
                      "Ratios eps_rr / eps_zz [-] of the radial-strain probes "
                      "run from each loaded branch state, each in [-0.5, 1] "
                      "(-0.5: isochoric, triaxial-like; 0 would repeat "
                      "uniaxial strain; 1: hydrostatic); they are not used "
                      "in the fit, so they measure the fitted law on "
                      "held-out paths (validation.csv). Empty: none.");
    declare_quantity(prm,
                     "Radial strain",
                     "0.02",
                     open(0.0, 0.2),
                     "-",
                     "Axial compressive logarithmic strain of each "
                     "radial-strain probe.");
    prm.declare_entry("Radial steps",
                      "8",
                      dealii::Patterns::Integer(1, 10000),
                      "Steps of each radial-strain probe, in [1, 1e4].");
    prm.leave_subsection();
  }

  void
  declare_database_parameters(dealii::ParameterHandler &prm)
  {
    // The deposited cell on the bonded path, balanced below jamming, as in
    // compax rve: the database, the multiscale tablet and the FE2 pool start
    // from the same loose state as the die's interior. compressed-gas and
    // frozen-history stay selectable for comparison.
    declare_rve_cell_parameters(prm, "deposited");
    declare_database_paths(prm);
    declare_rve_solver_parameters(prm, "none");
  }

  DatabaseStudy
  get_database_study(dealii::ParameterHandler &prm, const std::string &where)
  {
    DatabaseStudy study{get_rve_cell(prm), {}};
    auto         &spec = study.spec;
    spec.packing       = study.cell.packing;
    spec.loading       = get_rve_loading_options(prm);
    prm.enter_subsection("Paths");
    spec.final_density      = prm.get_double("Final relative density");
    spec.strain_step        = prm.get_double("Compaction strain step");
    spec.branch_densities   = get_real_list(prm, "Branch densities");
    const std::string list  = prm.get("Branch densities");
    spec.shear_strain       = prm.get_double("Shear strain");
    spec.shear_steps        = prm.get_integer("Shear steps");
    spec.confinement_strain = prm.get_double("Confinement strain");
    spec.radial_ratios      = get_real_list(prm, "Radial strain ratios");
    spec.radial_strain      = prm.get_double("Radial strain");
    spec.radial_steps       = prm.get_integer("Radial steps");
    prm.leave_subsection();

    if (spec.branch_densities.size() < 2)
      reject_entry(where + "Paths/Branch densities",
                   list,
                   "a density-dependent cap needs at least two branches");
    for (std::size_t k = 0; k < spec.branch_densities.size(); ++k)
      {
        const double rho = spec.branch_densities[k];
        if (!(rho > spec.packing.relative_density && rho <= spec.final_density)
            || (k > 0 && !(rho > spec.branch_densities[k - 1])))
          reject_entry(where + "Paths/Branch densities",
                       list,
                       "increasing densities in (Packing/Initial relative "
                       "density, Paths/Final relative density] = ("
                         + format_number(spec.packing.relative_density) + ", "
                         + format_number(spec.final_density) + "]");
      }
    return study;
  }

  void
  write_database_rows(const std::filesystem::path &folder,
                      const coupling::RveDatabase &db)
  {
    std::vector<std::string> columns{"branch",
                                     "path",
                                     "relative_density",
                                     "shear_strain"};
    for (const char *tensor : {"eps", "sigma"})
      for (std::string &column : voigt_columns(tensor))
        columns.push_back(std::move(column));
    columns.insert(columns.end(), {"p", "q"});
    CsvWriter csv(folder / "database.csv", std::move(columns));
    for (const coupling::DatabaseRow &r : db.rows)
      {
        csv << r.branch << r.path << r.relative_density << r.shear_strain;
        const dem::Vector6d eps
          = dem::to_voigt(dem::logarithmic_strain(r.deformation));
        for (int k = 0; k < 6; ++k)
          csv << eps[k];
        for (int k = 0; k < 6; ++k)
          csv << r.stress[k];
        const coupling::StressInvariants s = coupling::invariants(r.stress);
        csv << s.p << s.q;
        csv.end_row();
      }
    csv.close();
  }

  void
  write_database(coupling::Hdf5ArchiveWriter &h5,
                 const coupling::RveDatabase &db)
  {
    h5.write_attribute("units", "stress Pa, density and strain 1");
    // Path names: rows/path holds an index into path_names.
    std::vector<std::string> names;
    std::vector<double> branch, path, parent, density, shear, strain, stress,
      deformation;
    for (const coupling::DatabaseRow &r : db.rows)
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
    for (const coupling::DatabaseBranch &br : db.branches)
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

  coupling::RveDatabase
  read_database(const coupling::Hdf5ArchiveReader &h5)
  {
    coupling::RveDatabase    db;
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
        coupling::DatabaseRow row{static_cast<int>(branch[r]),
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
        const double            *v = &b[10 * k];
        coupling::DatabaseBranch br;
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
  write_database_archive(const std::filesystem::path &folder,
                         const coupling::RveDatabase &db,
                         const std::string           &parameters)
  {
    coupling::Hdf5ArchiveWriter h5((folder / "database.h5").string(),
                                   {coupling::archive_kind::rve_database,
                                    parameters});
    write_database(h5, db);
    h5.commit();
  }

  void
  write_dpc_table(const std::filesystem::path            &folder,
                  const std::vector<coupling::DpcFitRow> &rows)
  {
    CsvWriter csv(folder / "dpc_table.csv", fem::DpcTable::columns());
    for (const coupling::DpcFitRow &r : rows)
      {
        csv << r.relative_density << r.cohesion << r.friction_angle_deg
            << r.cap_eccentricity << r.cap_pressure << r.youngs_modulus
            << r.poisson_ratio;
        csv.end_row();
      }
    csv.close();
    const std::string script
      = "set datafile separator ','\n"
        "set terminal pngcairo size 1200,800\n"
        "set output 'dpc_table.png'\n"
        "set multiplot layout 2,3\n"
        "set xlabel 'relative density'\n"
        "set key off\n"
        "set title 'cohesion d [MPa]'\n"
        "plot 'dpc_table.csv' every ::1 using 1:($2/1e6) with linespoints\n"
        "set title 'friction angle [deg]'\n"
        "plot 'dpc_table.csv' every ::1 using 1:3 with linespoints\n"
        "set title 'cap eccentricity R'\n"
        "plot 'dpc_table.csv' every ::1 using 1:4 with linespoints\n"
        "set title 'cap pressure p_b [MPa]'\n"
        "plot 'dpc_table.csv' every ::1 using 1:($5/1e6) with linespoints\n"
        "set title 'E [GPa]'\n"
        "plot 'dpc_table.csv' every ::1 using 1:($6/1e9) with linespoints\n"
        "set title 'Poisson ratio'\n"
        "plot 'dpc_table.csv' every ::1 using 1:7 with linespoints\n"
        "unset multiplot\n";
    render_png(folder, "dpc_table.gp", script, "dpc_table.png");
  }


  fem::DpcTable
  to_dpc_table(const std::vector<coupling::DpcFitRow> &rows)
  {
    fem::DpcTable table;
    for (const coupling::DpcFitRow &r : rows)
      table.add_row(r.relative_density,
                    r.cohesion,
                    r.friction_angle_deg,
                    r.cap_eccentricity,
                    r.cap_pressure,
                    r.youngs_modulus,
                    r.poisson_ratio);
    table.validate();
    return table;
  }
} // namespace compax::cli

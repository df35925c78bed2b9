#include "apps/database/database_study.h"

#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/common/gnuplot.h"
#include "coupling/hdf5_archive.h"

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
    prm.leave_subsection();
  }

  void
  declare_database_parameters(dealii::ParameterHandler &prm)
  {
    declare_rve_cell_parameters(prm);
    declare_database_paths(prm);
    declare_rve_solver_parameters(prm);
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
    spec.shear_strain       = prm.get_double("Shear strain");
    spec.shear_steps        = prm.get_integer("Shear steps");
    spec.confinement_strain = prm.get_double("Confinement strain");
    prm.leave_subsection();

    const std::string list = prm.get("Paths/Branch densities");
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
    CsvWriter csv(folder / "database.csv",
                  {"branch",
                   "path",
                   "relative_density",
                   "shear_strain",
                   "sigma_xx",
                   "sigma_yy",
                   "sigma_zz",
                   "sigma_yz",
                   "sigma_xz",
                   "sigma_xy",
                   "p",
                   "q"});
    for (const coupling::DatabaseRow &r : db.rows)
      {
        csv << r.branch << r.path << r.relative_density << r.shear_strain;
        for (int k = 0; k < 6; ++k)
          csv << r.stress[k];
        const coupling::StressInvariants s = coupling::invariants(r.stress);
        csv << s.p << s.q;
        csv.end_row();
      }
    csv.close();
  }

  void
  write_database_archive(const std::filesystem::path &folder,
                         const coupling::RveDatabase &db)
  {
    coupling::Hdf5ArchiveWriter h5((folder / "database.h5").string());
    h5.write_attribute("format", "compax RVE response database 1");
    h5.write_attribute("units", "stress Pa, density and strain 1");
    std::vector<double> branch, density, shear, stress;
    for (const coupling::DatabaseRow &r : db.rows)
      {
        branch.push_back(r.branch);
        density.push_back(r.relative_density);
        shear.push_back(r.shear_strain);
        for (int k = 0; k < 6; ++k)
          stress.push_back(r.stress[k]);
      }
    h5.write_array("rows/branch", branch);
    h5.write_array("rows/relative_density", density);
    h5.write_array("rows/shear_strain", shear);
    h5.write_array("rows/stress", stress, {db.rows.size(), 6});
    std::vector<double> b;
    for (const coupling::DatabaseBranch &br : db.branches)
      b.insert(b.end(),
               {br.relative_density,
                br.unloaded_density,
                br.elastic.youngs_modulus,
                br.elastic.poisson_ratio,
                br.shear_failure.p,
                br.shear_failure.q,
                br.confined_shear_failure.p,
                br.confined_shear_failure.q});
    h5.write_array("branches", b, {db.branches.size(), 8});
    h5.write_attribute("branches_columns",
                       "relative_density, unloaded_density, E, nu, "
                       "shear_p, shear_q, confined_shear_p, "
                       "confined_shear_q");
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

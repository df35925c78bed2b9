#include "apps/compare/compare_parameters.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "coupling/parameters/material_parameters.h"
#include "coupling/parameters/rve_parameters.h"

#include <cmath>
#include <cstdlib>

namespace compax::cli
{
  namespace
  {
    const std::vector<std::string> material_entries = {"Radius",
                                                       "Young's modulus",
                                                       "Poisson's ratio",
                                                       "Plastic stiffness",
                                                       "Plastic exponent",
                                                       "Surface energy"};
    const std::vector<std::string> bonding_entries
      = {"Fracture toughness from energies",
         "Fracture toughness",
         "Plastic dissipation",
         "Regularization parameter"};

    Settings
    copy_section(dealii::ParameterHandler       &prm,
                 const std::string              &section,
                 const std::vector<std::string> &entries)
    {
      Settings s;
      prm.enter_subsection(section);
      for (const std::string &e : entries)
        s.emplace_back(section + "/" + e, prm.get(e));
      prm.leave_subsection();
      return s;
    }

    /// RVE/Final relative density: empty means the die's.
    double
    rve_final_density(const std::string &entry, const double die_final)
    {
      if (entry.find_first_not_of(" \t") == std::string::npos)
        return die_final;
      char        *end   = nullptr;
      const double value = std::strtod(entry.c_str(), &end);
      if (end == entry.c_str()
          || std::string(end).find_first_not_of(" \t") != std::string::npos
          || !(value >= die_final && value <= 0.99))
        reject_entry("RVE/Final relative density",
                     entry,
                     "a relative density in [Die/Final relative density = "
                       + format_number(die_final) + ", 0.99], or empty");
      return value;
    }
  } // namespace

  void
  declare_compare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Bool;
    using dealii::Patterns::Integer;
    prm.enter_subsection("Compare");
    prm.declare_entry("FE2",
                      "true",
                      Bool(),
                      "Also run the tablet in multiscale-fe2 mode (an RVE "
                      "per quadrature point) and compare it with the "
                      "database mode (comparison fe2_vs_database). If the "
                      "FE2 run stops, the densities it did not reach are "
                      "left empty in compare.csv and the reason is in "
                      "compare.md. Unit: none.");
    prm.declare_entry("FE2 particles per RVE",
                      "60",
                      Integer(2, 100000),
                      "Spheres in each FE2 RVE, in [2, 1e5]. Unit: -.");
    prm.declare_entry("FE2 pool size",
                      "1",
                      Integer(1, 1000),
                      "Distinct FE2 RVE packings (tablet Multiscale/Pool "
                      "size), in [1, 1000]. Unit: -.");
    prm.declare_entry("FE2 radial cells",
                      "1",
                      Integer(1, 256),
                      "Radial cells of the FE2 tablet mesh (the "
                      "frictionless die compacts the tablet uniformly, so "
                      "one cell suffices), in [1, 256]. Unit: -.");
    prm.declare_entry("FE2 compaction steps",
                      "12",
                      Integer(1, 100000),
                      "Load steps of the FE2 tablet's compaction (it is "
                      "not unloaded), in [1, 1e5]. Unit: -.");
    prm.declare_entry("FE2 max step cuts",
                      "3",
                      Integer(0, 30),
                      "Times an FE2 load step may be halved before the FE2 "
                      "run stops, in [0, 30]. Unit: -.");
    declare_quantity(prm,
                     "FE2 tangent floor modulus",
                     "1e6",
                     non_negative(),
                     "Pa",
                     "Tablet Multiscale/Tangent floor modulus of the FE2 "
                     "run.");
    prm.leave_subsection();

    prm.enter_subsection("Material");
    coupling::declare_particle_material(prm, coupling::material_1);
    prm.leave_subsection();

    coupling::declare_bonding_parameters(prm,
                                         coupling::BondedBodies::one_species);

    prm.enter_subsection("Die");
    declare_quantity(prm,
                     "Die diameter",
                     "4e-3",
                     positive(),
                     "m",
                     "Diameter D of the rigid cylindrical die, of the "
                     "particle simulation and of the tablet model.");
    prm.declare_entry("Number of particles",
                      "400",
                      Integer(1, 10000000),
                      "Particles deposited in the die (compax die "
                      "Packing/Number of particles), in [1, 1e7]. The "
                      "tablet's fill height and initial relative density "
                      "are those of the deposited bed. Unit: -.");
    prm.declare_entry("Seed",
                      "1",
                      Integer(0),
                      "Seed of the die bed's packing, >= 0. Unit: -.");
    declare_quantity(prm,
                     "Final relative density",
                     "0.87",
                     open(0.0, 1.0),
                     "-",
                     "In-die relative density at which compaction ends, in "
                     "the particle die, the RVE database and the tablet "
                     "runs.");
    prm.declare_entry("Compaction steps",
                      "30",
                      Integer(1, 100000),
                      "Density steps of the particle die compaction, in "
                      "[1, 1e5]. Unit: -.");
    declare_quantity(prm,
                     "Unloading points",
                     "0.75, 0.79, 0.83, 0.87",
                     dealii::Patterns::List(dealii::Patterns::Double(0, 1)),
                     "-",
                     "In-die relative densities at which the particle bed "
                     "is unloaded (its E and nu, Gonzalez 2018 Sec. 5.7) "
                     "and at which the RVE database branches (its E and "
                     "nu): at least two, increasing, the last one the "
                     "Final relative density (the tablet is unloaded "
                     "there, for the ejection pressure).");
    declare_quantity(prm,
                     "Die-wall friction coefficient",
                     "1",
                     non_negative(),
                     "-",
                     "Coulomb coefficient mu of the ejection pressure "
                     "mu F_radial / A_punch (Gonzalez 2018 Sec. 5.4), "
                     "applied to the residual die-wall force after "
                     "unloading of both the particle bed and the tablet "
                     "model; compaction itself is frictionless in both, as "
                     "in the particle simulation.");
    prm.leave_subsection();

    prm.enter_subsection("RVE");
    prm.declare_entry("Number of particles",
                      "200",
                      Integer(2, 10000000),
                      "Spheres in the periodic RVE of the response "
                      "database, in [2, 1e7]. Unit: -.");
    prm.declare_entry("Seed",
                      "1",
                      Integer(0),
                      "Seed of the RVE packing, >= 0. Unit: -.");
    declare_quantity(prm,
                     "Compaction strain step",
                     "0.01",
                     open(0.0, 0.1),
                     "-",
                     "Axial logarithmic strain per RVE compaction step.");
    prm.declare_entry("Shear steps",
                      "10",
                      Integer(2, 10000),
                      "Steps of each shear probe of the database, in [2, "
                      "1e4]. Unit: -.");
    declare_quantity(
      prm,
      "Loose branches",
      "0.65, 0.7",
      dealii::Patterns::List(dealii::Patterns::Double(0, 1), 0),
      "-",
      "Further densities at which the RVE database branches, below the "
      "first of Die/Unloading points (the larger ones are ignored), so "
      "that the tablet's DPC table reaches into the loose powder: below "
      "its lowest row the table keeps that row's cohesion and moduli (p_b "
      "extrapolates), so a table through the unloading points alone gives "
      "the loose powder the stiffness of a compact (measured on the "
      "built-in default: 2.7 MPa at rho 0.58, where the particle die "
      "carries 0.18 MPa). Each must lie where the RVE is jammed (an "
      "unjammed branch has no moduli and the database stops); empty: "
      "none.");
    prm.declare_entry(
      "Final relative density",
      "",
      dealii::Patterns::Anything(),
      "Relative density the RVE's uniaxial compaction path reaches, in "
      "[Die/Final relative density, 0.99]; empty: Die/Final relative "
      "density. The die's interior is denser than the die average (its "
      "wall layer is looser), so interior.csv needs the RVE beyond the "
      "die's final density to compare the interior's last states. Unit: "
      "-.");
    prm.leave_subsection();

    prm.enter_subsection("Tablet");
    prm.declare_entry("Radial cells",
                      "2",
                      Integer(1, 256),
                      "Radial cells of the database-mode tablet mesh, in "
                      "[1, 256]. Unit: -.");
    prm.declare_entry("Compaction steps",
                      "40",
                      Integer(1, 100000),
                      "Load steps of the tablet's compaction, in [1, 1e5]. "
                      "Unit: -.");
    prm.declare_entry("Unloading steps",
                      "12",
                      Integer(1, 100000),
                      "Load steps of the tablet's unloading (the punch is "
                      "withdrawn by 40 % of the compacted height, past the "
                      "springback), in [1, 1e5]. Unit: -.");
    prm.leave_subsection();
  }

  CompareSetup
  read_compare_setup(dealii::ParameterHandler &prm)
  {
    CompareSetup c;
    c.material = copy_section(prm, "Material", material_entries);
    c.bonding  = copy_section(prm, "Bonding", bonding_entries);

    prm.enter_subsection("Die");
    c.comparison.die_diameter     = prm.get_double("Die diameter");
    c.comparison.final_density    = prm.get_double("Final relative density");
    c.comparison.unloading_points = get_real_list(prm, "Unloading points");
    c.unloading_list              = prm.get("Unloading points");
    c.comparison.wall_friction
      = prm.get_double("Die-wall friction coefficient");
    c.die
      = {{"Packing/Die diameter", prm.get("Die diameter")},
         {"Packing/Number of particles", prm.get("Number of particles")},
         {"Packing/Seed", prm.get("Seed")},
         {"Protocol/Final relative density", prm.get("Final relative density")},
         {"Protocol/Compaction steps", prm.get("Compaction steps")},
         {"Protocol/Unloading points", prm.get("Unloading points")},
         {"Protocol/Die-wall friction coefficient",
          prm.get("Die-wall friction coefficient")},
         {"Protocol/Eject", "true"},
         {"Protocol/Checkpoint interval", "0"}};
    prm.leave_subsection();
    for (const auto &entry : c.material)
      c.die.push_back(entry);
    for (const auto &entry : c.bonding)
      c.die.push_back(entry);

    const auto &u = c.comparison.unloading_points;
    if (u.size() < 2)
      reject_entry("Die/Unloading points",
                   c.unloading_list,
                   "needs at least two densities (the RVE database "
                   "fits a density-dependent cap through its branches)");
    for (std::size_t k = 0; k < u.size(); ++k)
      if (!(u[k] > 0.0 && u[k] <= c.comparison.final_density)
          || (k > 0 && !(u[k] > u[k - 1])))
        reject_entry("Die/Unloading points",
                     c.unloading_list,
                     "increasing densities in (0, Final relative density "
                     "= "
                       + format_number(c.comparison.final_density)
                       + "] are needed");
    if (std::abs(u.back() - c.comparison.final_density) > 1e-12)
      reject_entry("Die/Unloading points",
                   c.unloading_list,
                   "the last one must be the Final relative density "
                     + format_number(c.comparison.final_density)
                     + ": the ejection pressures are compared there");

    prm.enter_subsection("RVE");
    c.rve_particles             = prm.get_integer("Number of particles");
    c.rve_seed                  = prm.get_integer("Seed");
    c.rve_strain_step           = prm.get_double("Compaction strain step");
    c.rve_shear_steps           = prm.get_integer("Shear steps");
    c.comparison.loose_branches = get_real_list(prm, "Loose branches");
    c.rve_final_density = rve_final_density(prm.get("Final relative density"),
                                            c.comparison.final_density);
    prm.leave_subsection();

    prm.enter_subsection("Tablet");
    c.tablet_cells           = prm.get_integer("Radial cells");
    c.tablet_steps           = prm.get_integer("Compaction steps");
    c.tablet_unloading_steps = prm.get_integer("Unloading steps");
    prm.leave_subsection();

    prm.enter_subsection("Compare");
    c.fe2           = prm.get_bool("FE2");
    c.fe2_particles = prm.get_integer("FE2 particles per RVE");
    c.fe2_pool      = prm.get_integer("FE2 pool size");
    c.fe2_cells     = prm.get_integer("FE2 radial cells");
    c.fe2_steps     = prm.get_integer("FE2 compaction steps");
    c.fe2_cuts      = prm.get_integer("FE2 max step cuts");
    c.fe2_floor     = prm.get_double("FE2 tangent floor modulus");
    prm.leave_subsection();
    return c;
  }
} // namespace compax::cli

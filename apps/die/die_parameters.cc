#include "apps/die/die_parameters.h"

#include "apps/cli/parameters.h"
#include "apps/common/material_parameters.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace compax::cli
{
  void
  declare_die_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    declare_particle_material(prm, material_1);
    prm.leave_subsection();

    prm.enter_subsection("Bonding");
    prm.declare_entry("Fracture toughness from energies",
                      "false",
                      dealii::Patterns::Bool(),
                      "true: K_Ic = sqrt(2 (2 omega + G_p) E) from the "
                      "Material's surface energy omega (Gonzalez 2018 after "
                      "Eq. 5); false: the Fracture toughness entry.");
    declare_quantity(prm,
                     "Fracture toughness",
                     "1.26e6",
                     non_negative(),
                     "Pa m^1/2",
                     "Fracture toughness K_Ic of the solid bridges between "
                     "particles (Material 1 of Gonzalez 2018, Table 1); 0 "
                     "for no bonding.");
    declare_quantity(prm,
                     "Plastic dissipation",
                     "0",
                     non_negative(),
                     "J/m^2",
                     "G_p added to the surface energies when K_Ic is "
                     "computed from energies.");
    declare_quantity(prm,
                     "Regularization parameter",
                     "0.01",
                     positive(),
                     "-",
                     "xi_B of the regularized law, Eq. (4).");
    prm.declare_entry("Bridges with walls",
                      "false",
                      dealii::Patterns::Bool(),
                      "Whether solid bridges form between particles and the "
                      "punches or die wall (same K_Ic).");
    prm.leave_subsection();

    prm.enter_subsection("Packing");
    prm.declare_entry("Number of particles",
                      "400",
                      dealii::Patterns::Integer(1, 10000000),
                      "Particles dropped by ballistic deposition "
                      "(Jullien & Meakin 1989), in [1, 1e7].");
    declare_quantity(prm,
                     "Die diameter",
                     "4e-3",
                     positive(),
                     "m",
                     "Diameter D of the rigid cylindrical die.");
    declare_quantity(prm,
                     "Log-normal sigma",
                     "0",
                     non_negative(),
                     "-",
                     "Standard deviation of ln R of a log-normal size "
                     "distribution with median the Material's Radius; 0 "
                     "for a monodisperse bed.");
    declare_quantity(prm,
                     "Minimum radius",
                     "0",
                     non_negative(),
                     "m",
                     "Lower cut-off of the log-normal distribution.");
    declare_quantity(prm,
                     "Maximum radius",
                     "1",
                     positive(),
                     "m",
                     "Upper cut-off of the log-normal distribution.");
    prm.declare_entry("Seed",
                      "1",
                      dealii::Patterns::Integer(0),
                      "Seed of the packing's random numbers (same seed, "
                      "same packing), >= 0.");
    prm.leave_subsection();

    prm.enter_subsection("Protocol");
    declare_quantity(prm,
                     "Final relative density",
                     "0.87",
                     open(0.0, 1.0),
                     "-",
                     "In-die relative density at which compaction ends.");
    prm.declare_entry("Compaction steps",
                      "30",
                      dealii::Patterns::Integer(1, 100000),
                      "Equal density steps from the packing's density to "
                      "the final density (load steps are cut back "
                      "automatically when needed), in [1, 100000].");
    declare_quantity(prm,
                     "Unloading points",
                     "0.75, 0.79, 0.83, 0.87",
                     dealii::Patterns::List(dealii::Patterns::Double(0, 1)),
                     "-",
                     "In-die relative densities rho_max at which an "
                     "unloading branch starts from the compaction path "
                     "(comma-separated, each in (0, 1), at most the final "
                     "density; empty for none).");
    declare_quantity(prm,
                     "Unloading step",
                     "2e-3",
                     open(0.0, 0.5),
                     "-",
                     "Upper-punch withdrawal per unloading step as a "
                     "fraction of the punch gap at the unloading point.");
    prm.declare_entry("Eject",
                      "true",
                      dealii::Patterns::Bool(),
                      "Whether each unloaded compact is ejected (the die "
                      "wall is released in steps).");
    declare_quantity(prm,
                     "Die-wall friction coefficient",
                     "1",
                     non_negative(),
                     "-",
                     "Coulomb coefficient mu of the ejection pressure "
                     "mu F_radial / A_punch (Gonzalez 2018, Sec. 5.4).");
    declare_quantity(prm,
                     "Ejection step",
                     "2e-4",
                     open(0.0, 0.1),
                     "-",
                     "Die-radius increase per ejection step, as a fraction "
                     "of the die radius.");
    prm.declare_entry("Rerun branch from",
                      "",
                      dealii::Patterns::Anything(),
                      "Path of a branch checkpoint written by an earlier run "
                      "(OUTDIR/checkpoints/branch-<k>.h5): skip packing and "
                      "compaction and rerun that unloading branch (unloading "
                      "and ejection) from the saved state, with this file's "
                      "other protocol and solver settings. Empty: run the "
                      "whole study.");
    prm.declare_entry("Maximum ejection steps",
                      "40",
                      dealii::Patterns::Integer(1, 100000),
                      "Ejection steps before the die wall is removed "
                      "altogether, in [1, 100000].");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    declare_quantity(prm,
                     "Force tolerance",
                     "1e-6",
                     open(0.0, 1.0),
                     "-",
                     "Converged when the largest net force on a particle is "
                     "below this times the mean contact force.");
    declare_quantity(prm,
                     "Step tolerance",
                     "1e-4",
                     open(0.0, 1.0),
                     "-",
                     "... and the largest particle displacement of the last "
                     "Newton step is below this times the mean radius.");
    prm.declare_entry("Maximum iterations",
                      "200",
                      dealii::Patterns::Integer(1, 1000000),
                      "Trust-region Newton iterations per load step before "
                      "the step is cut back, in [1, 1e6].");
    prm.leave_subsection();
  }

  DieStudy
  get_die_study(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    const dem::ElastoplasticMaterial material = get_particle_material(prm);
    const double                     radius   = get_particle_radius(prm);
    const double                     omega    = get_surface_energy(prm);
    prm.leave_subsection();

    prm.enter_subsection("Bonding");
    double toughness = prm.get_double("Fracture toughness");
    if (prm.get_bool("Fracture toughness from energies"))
      toughness
        = dem::fracture_toughness_from_energies(material,
                                                omega,
                                                material,
                                                omega,
                                                prm.get_double(
                                                  "Plastic dissipation"));
    dem::ContactModel model(material,
                            toughness,
                            prm.get_double("Regularization parameter"));
    model.wall_bonding = prm.get_bool("Bridges with walls");
    prm.leave_subsection();

    prm.enter_subsection("Packing");
    dem::DepositionParameters deposition;
    deposition.n_particles         = prm.get_integer("Number of particles");
    deposition.die_diameter        = prm.get_double("Die diameter");
    deposition.sizes.median_radius = radius;
    deposition.sizes.log_sigma     = prm.get_double("Log-normal sigma");
    deposition.sizes.min_radius    = prm.get_double("Minimum radius");
    deposition.sizes.max_radius    = prm.get_double("Maximum radius");
    deposition.seed = static_cast<std::uint64_t>(prm.get_integer("Seed"));
    if (deposition.die_diameter <= 4 * radius)
      reject_entry("Packing/Die diameter",
                   format_number(deposition.die_diameter),
                   "the die must be wider than two particle diameters (> "
                     + format_number(4 * radius) + " m)");
    if (deposition.sizes.log_sigma > 0
        && deposition.sizes.min_radius >= deposition.sizes.max_radius)
      reject_entry("Packing/Minimum radius",
                   format_number(deposition.sizes.min_radius),
                   "must be below the Maximum radius ("
                     + format_number(deposition.sizes.max_radius) + " m)");
    prm.leave_subsection();

    prm.enter_subsection("Protocol");
    dem::DieProtocol protocol;
    const double     final_density = prm.get_double("Final relative density");
    const int        steps         = prm.get_integer("Compaction steps");
    protocol.unloading_points      = get_real_list(prm, "Unloading points");
    const std::string rerun        = prm.get("Rerun branch from");
    for (const double u : protocol.unloading_points)
      if (rerun.empty() && (u <= 0.0 || u > final_density))
        reject_entry("Protocol/Unloading points",
                     format_number(u),
                     "each unloading point must lie in (0, Final relative "
                     "density = "
                       + format_number(final_density) + "]");
    protocol.unloading_step = prm.get_double("Unloading step");
    protocol.eject          = prm.get_bool("Eject");
    protocol.friction_coefficient
      = prm.get_double("Die-wall friction coefficient");
    protocol.ejection_step      = prm.get_double("Ejection step");
    protocol.max_ejection_steps = prm.get_integer("Maximum ejection steps");
    if (!rerun.empty() && !std::filesystem::is_regular_file(rerun))
      reject_entry("Protocol/Rerun branch from",
                   rerun,
                   "no such checkpoint file");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    dem::EquilibriumOptions equilibrium;
    equilibrium.force_tolerance = prm.get_double("Force tolerance");
    equilibrium.step_tolerance  = prm.get_double("Step tolerance");
    equilibrium.max_iterations  = prm.get_integer("Maximum iterations");
    prm.leave_subsection();

    return {
      deposition, model, protocol, equilibrium, final_density, steps, rerun};
  }
} // namespace compax::cli

#include "apps/mcdem/mcdem_parameters.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "dem/periodic/size_distribution_fit.h"

#include <sstream>

namespace compax::cli
{
  void
  declare_mcdem_parameters(dealii::ParameterHandler &prm,
                           const double              mass_scaling,
                           const double              strain_rate)
  {
    prm.enter_subsection("Material");
    declare_quantity(prm,
                     "Young's modulus",
                     "2.58e8",
                     positive(),
                     "Pa",
                     "Young's modulus E of the particles (Table 2; MCC-A "
                     "2.58e8, MCC-P 1.34e9).");
    declare_quantity(prm,
                     "Poisson's ratio",
                     "0.30",
                     open(-1.0, 0.5),
                     "-",
                     "Poisson's ratio nu of the particles; also the nu of the "
                     "multi-contact term beta nu A P (Eq. 13).");
    declare_quantity(prm,
                     "Density",
                     "1541.1",
                     positive(),
                     "kg/m^3",
                     "True density of the particles (Tables 1-2).");
    declare_quantity(prm,
                     "Wall Young's modulus",
                     "7.62e10",
                     positive(),
                     "Pa",
                     "Young's modulus of the plates.");
    declare_quantity(prm,
                     "Wall Poisson's ratio",
                     "0.31",
                     open(-1.0, 0.5),
                     "-",
                     "Poisson's ratio of the plates.");
    declare_quantity(prm,
                     "Restitution particle-particle",
                     "0.352",
                     RealInterval(0.0, true, 1.0, false),
                     "-",
                     "Coefficient of restitution of particle-particle "
                     "contacts; sets the Hertzian dashpot (exactly, for the "
                     "elastic law).");
    declare_quantity(prm,
                     "Restitution particle-wall",
                     "0.352",
                     RealInterval(0.0, true, 1.0, false),
                     "-",
                     "Coefficient of restitution of particle-plate contacts.");
    declare_quantity(prm,
                     "Sliding friction particle-particle",
                     "0.561",
                     non_negative(),
                     "-",
                     "Coulomb friction mu_s(pp).");
    declare_quantity(prm,
                     "Sliding friction particle-wall",
                     "0.707",
                     non_negative(),
                     "-",
                     "Coulomb friction mu_s(pw).");
    declare_quantity(prm,
                     "Rolling friction particle-particle",
                     "0.3",
                     non_negative(),
                     "-",
                     "Rolling friction mu_r(pp) of the constant directional "
                     "torque, Eq. (5), with R_r = R*.");
    declare_quantity(prm,
                     "Rolling friction particle-wall",
                     "0.01",
                     non_negative(),
                     "-",
                     "Rolling friction mu_r(pw).");
    prm.leave_subsection();

    prm.enter_subsection("Multi-contact law");
    declare_quantity(prm,
                     "Unloading stiffness ratio",
                     "120",
                     RealInterval(1.0, false, 1e6, false),
                     "-",
                     "k2/k1, the largest un/reloading stiffness (Eq. 11; "
                     "Table 3: 120). 1 with kc/k1 = 0 and beta = 0 is the "
                     "conventional Hertz-Mindlin model.");
    declare_quantity(prm,
                     "Adhesion stiffness ratio",
                     "0.5",
                     non_negative(),
                     "-",
                     "kc/k1 of the adhesive branch (Eq. 10; Table 3: 0.5).");
    declare_quantity(prm,
                     "Plasticity depth",
                     "0.99",
                     non_negative(),
                     "-",
                     "phi_f of Eq. (12) (Table 3: 0.99).");
    declare_quantity(prm,
                     "Multi-contact prefactor",
                     "1.3",
                     non_negative(),
                     "-",
                     "beta of Eqs. (13)-(14) (Table 3: MCC-A 1.3, MCC-P 1.5); "
                     "0 switches the multi-contact term off.");
    declare_quantity(prm,
                     "Pull-off force",
                     "0",
                     closed(-1.0, 1.0),
                     "N",
                     "Constant F_0 of Eq. (6), added while in contact.");
    prm.leave_subsection();

    prm.enter_subsection("Particle size distribution");
    declare_quantity(prm,
                     "x10",
                     "82.9e-6",
                     positive(),
                     "m",
                     "Volume (Q3) 10% diameter (Table 1; MCC-P 28.3e-6).");
    declare_quantity(prm,
                     "x50",
                     "224.6e-6",
                     positive(),
                     "m",
                     "Volume (Q3) median diameter (Table 1; MCC-P 86.5e-6).");
    declare_quantity(prm,
                     "x90",
                     "379.3e-6",
                     positive(),
                     "m",
                     "Volume (Q3) 90% diameter (Table 1; MCC-P 173.8e-6). A "
                     "log-normal is fitted to x10, x50, x90 by least squares "
                     "in ln x and sampled by number (Hatch-Choate).");
    declare_quantity(prm,
                     "Minimum diameter",
                     "82.9e-6",
                     non_negative(),
                     "m",
                     "Lower cut-off of the sampled diameters; small particles "
                     "set the time step.");
    declare_quantity(prm,
                     "Maximum diameter",
                     "379.3e-6",
                     positive(),
                     "m",
                     "Upper cut-off; must stay below the cell size.");
    prm.leave_subsection();

    prm.enter_subsection("Cell");
    prm.declare_entry("Cell sizes",
                      "0.6e-3",
                      dealii::Patterns::List(dealii::Patterns::Double(0.0), 1),
                      "Edges of the cubic cells, periodic in x and y between "
                      "plates in z [m]. Several values run the RVE-size study "
                      "of Sec. 4.1 (paper: 0.6e-3, 0.8e-3, 1.0e-3, 1.4e-3) "
                      "with the same statistics. Unit: m.");
    declare_quantity(prm,
                     "Packing density",
                     "0.59",
                     open(0.0, 0.74),
                     "-",
                     "Solid fraction the particles grow to (paper: 0.59).");
    prm.declare_entry("Number of particles",
                      "0",
                      dealii::Patterns::Integer(0, 10000000),
                      "If positive: insert this many particles and size the "
                      "cube to the packing density (e.g. 698 for the paper's "
                      "MCC-A RVE); 0 fills the given cell sizes. Unit: -.");
    prm.declare_entry("Seed",
                      "1",
                      dealii::Patterns::Integer(0),
                      "Seed of the random insertion. Unit: -.");
    declare_quantity(prm,
                     "Initial radius fraction",
                     "0.5",
                     open(0.0, 1.0),
                     "-",
                     "Radii at insertion as a fraction of the final radii.");
    prm.leave_subsection();

    prm.enter_subsection("Protocol");
    declare_quantity(prm,
                     "Growth time",
                     "2e-4",
                     positive(),
                     "s",
                     "Time to grow the particles to full size (elastic, "
                     "frictionless law).");
    declare_quantity(prm,
                     "Relaxation time",
                     "1e-4",
                     non_negative(),
                     "s",
                     "Free relaxation after the growth.");
    declare_quantity(prm,
                     "Strain rate",
                     format_number(strain_rate),
                     positive(),
                     "1/s",
                     "Engineering strain rate of the top plate, compression "
                     "and decompression.");
    declare_quantity(prm,
                     "Target strain",
                     "0.57",
                     open(0.0, 1.0),
                     "-",
                     "Loading stops at this strain (paper: 0.57 MCC-A, 0.53 "
                     "MCC-P for calibration; 0.71, 0.69 for verification).");
    declare_quantity(prm,
                     "Target stress",
                     "0",
                     non_negative(),
                     "Pa",
                     "... or at this plate stress if positive (paper: 29e6, "
                     "25e6, 180e6, 185e6).");
    prm.declare_entry("Decompress",
                      "true",
                      dealii::Patterns::Bool(),
                      "Unload after loading until the plate stress vanishes.");
    declare_quantity(prm,
                     "Output strain interval",
                     "0.005",
                     positive(),
                     "-",
                     "A row of mcdem.csv every this much strain.");
    prm.leave_subsection();

    prm.enter_subsection("Numerics");
    declare_quantity(prm,
                     "Rayleigh time step fraction",
                     "0.2",
                     open(0.0, 1.0),
                     "-",
                     "dt <= fraction x Rayleigh time step of the smallest "
                     "particle.");
    declare_quantity(prm,
                     "Stiffness time step fraction",
                     "0.3",
                     open(0.0, 1.0),
                     "-",
                     "dt <= fraction x 2/omega_max from the current contact "
                     "stiffnesses (the plastic law's unloading branch is up "
                     "to k2/k1 times stiffer than Hertz).");
    declare_quantity(prm,
                     "Mass scaling",
                     format_number(mass_scaling),
                     RealInterval(1.0, false, 1e6, false),
                     "-",
                     "Factor on all masses and inertias (density scaling for "
                     "quasi-static runs; 1 = physical). The default cell gives "
                     "the same peak stress to 0.1% with 1 and 10.");
    prm.leave_subsection();
  }

  McdemSetup
  get_mcdem_setup(dealii::ParameterHandler &prm)
  {
    McdemSetup s;
    auto      &m = s.material;
    prm.enter_subsection("Material");
    m.youngs_modulus      = prm.get_double("Young's modulus");
    m.poisson_ratio       = prm.get_double("Poisson's ratio");
    m.density             = prm.get_double("Density");
    m.wall_youngs_modulus = prm.get_double("Wall Young's modulus");
    m.wall_poisson_ratio  = prm.get_double("Wall Poisson's ratio");
    m.particle_particle
      = {prm.get_double("Restitution particle-particle"),
         prm.get_double("Sliding friction particle-particle"),
         prm.get_double("Rolling friction particle-particle")};
    m.particle_wall = {prm.get_double("Restitution particle-wall"),
                       prm.get_double("Sliding friction particle-wall"),
                       prm.get_double("Rolling friction particle-wall")};
    prm.leave_subsection();

    prm.enter_subsection("Multi-contact law");
    m.normal_law.unloading_stiffness_ratio
      = prm.get_double("Unloading stiffness ratio");
    m.normal_law.adhesion_stiffness_ratio
      = prm.get_double("Adhesion stiffness ratio");
    m.normal_law.plasticity_depth = prm.get_double("Plasticity depth");
    m.normal_law.multicontact_prefactor
      = prm.get_double("Multi-contact prefactor");
    m.normal_law.pull_off_force = prm.get_double("Pull-off force");
    m.normal_law.poisson_ratio  = m.poisson_ratio;
    prm.leave_subsection();

    prm.enter_subsection("Particle size distribution");
    const double x10 = prm.get_double("x10"), x50 = prm.get_double("x50"),
                 x90   = prm.get_double("x90");
    const double d_min = prm.get_double("Minimum diameter"),
                 d_max = prm.get_double("Maximum diameter");
    prm.leave_subsection();
    if (!(x10 < x50 && x50 < x90))
      reject_entry("Particle size distribution/x50",
                   format_number(x50),
                   "need x10 < x50 < x90");
    if (!(d_max > d_min))
      reject_entry("Particle size distribution/Maximum diameter",
                   format_number(d_max),
                   "must exceed the minimum diameter " + format_number(d_min));
    const auto fit           = dem::fit_volume_log_normal(x10, x50, x90);
    s.fitted_median_diameter = fit.median_diameter;
    s.fitted_log_sigma       = fit.log_sigma;
    s.rve.sizes = dem::number_radius_distribution(fit, d_min, d_max);

    prm.enter_subsection("Cell");
    s.cell_sizes          = get_real_list(prm, "Cell sizes");
    s.rve.packing_density = prm.get_double("Packing density");
    s.rve.particle_count  = prm.get_integer("Number of particles");
    s.rve.seed            = prm.get_integer("Seed");
    s.rve.initial_scale   = prm.get_double("Initial radius fraction");
    prm.leave_subsection();
    for (const double L : s.cell_sizes)
      if (s.rve.particle_count == 0 && !(L > 1.05 * d_max))
        reject_entry("Cell/Cell sizes",
                     format_number(L),
                     "every cell must be wider than the maximum diameter "
                       + format_number(d_max) + " m (with 5% room)");
    s.rve.cell_size = s.cell_sizes.front();

    prm.enter_subsection("Protocol");
    auto &p                  = s.protocol;
    p.growth_time            = prm.get_double("Growth time");
    p.relaxation_time        = prm.get_double("Relaxation time");
    p.strain_rate            = prm.get_double("Strain rate");
    p.target_strain          = prm.get_double("Target strain");
    p.target_stress          = prm.get_double("Target stress");
    p.decompress             = prm.get_bool("Decompress");
    p.output_strain_interval = prm.get_double("Output strain interval");
    prm.leave_subsection();

    prm.enter_subsection("Numerics");
    s.settings.rayleigh_factor = prm.get_double("Rayleigh time step fraction");
    s.settings.stiffness_factor
      = prm.get_double("Stiffness time step fraction");
    s.settings.mass_scaling = prm.get_double("Mass scaling");
    prm.leave_subsection();
    return s;
  }
} // namespace compax::cli

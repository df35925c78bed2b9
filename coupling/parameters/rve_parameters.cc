#include "coupling/parameters/rve_parameters.h"

#include "coupling/parameters/contact_parameters.h"
#include "coupling/parameters/equilibrium_parameters.h"
#include "coupling/parameters/material_parameters.h"
#include "coupling/parameters/voigt_columns.h"
#include "dem/periodic/size_distribution_fit.h"
#include "dem/rve/rve_packing.h"
#include "input/canonical_parameters.h"
#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"
#include "io/csv_table.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace compax::coupling
{

  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// Mean R^3 of the (untruncated) radius distribution [m^3].
    double
    mean_cubed_radius(const dem::SizeDistribution &s)
    {
      return std::pow(s.median_radius, 3)
             * std::exp(4.5 * s.log_sigma * s.log_sigma);
    }

    /// Rejects a particle count whose cell would be narrower than a
    /// particle plus the Verlet skin at the smallest width along the path
    /// (the contact search needs 2 R_max + skin, Giannis 2021 Sec. 4.1
    /// warns that small cells underestimate the stress anyway).
    void
    check_cell_width(const std::string &entry,
                     const std::size_t  n,
                     const RveStudy    &s)
    {
      const auto  &sizes = s.packing.sizes;
      const double R_max
        = s.packing.sizes.log_sigma > 0.0
            ? std::min(sizes.max_radius,
                       sizes.median_radius * std::exp(3.0 * sizes.log_sigma))
            : sizes.median_radius;
      const double skin = s.packing.skin * sizes.median_radius;
      const double L0 = std::cbrt(n * 4.0 / 3.0 * pi * mean_cubed_radius(sizes)
                                  / s.packing.relative_density);
      double       narrowest = L0;
      if (s.path == RvePath::uniaxial)
        narrowest = L0 * s.packing.relative_density / s.target_density;
      else if (s.path == RvePath::hydrostatic)
        narrowest
          = L0 * std::cbrt(s.packing.relative_density / s.target_density);
      const double needed = 2.0 * R_max + skin;
      if (narrowest < needed)
        input::reject_entry(
          entry,
          std::to_string(n),
          "too few particles: the cell would be "
            + input::format_number(narrowest)
            + " m wide along the path, below the largest diameter "
              "plus the Verlet skin ("
            + input::format_number(needed) + " m)");
    }
  } // namespace

  const std::vector<std::string> &
  strain_csv_columns()
  {
    static const std::vector<std::string> names = voigt_columns("eps");
    return names;
  }

  std::vector<Eigen::Matrix3d>
  read_strain_increments(const std::string &file, const std::string &entry)
  {
    std::vector<Eigen::Matrix3d> increments;
    try
      {
        const io::CsvTable table = io::CsvTable::read(file);
        const auto        &names = strain_csv_columns();
        std::size_t        slot[6];
        try
          {
            for (int b = 0; b < 6; ++b)
              slot[b] = table.column(names[b]);
          }
        catch (const io::CsvError &e)
          {
            throw io::CsvError(file,
                               e.reason()
                                 + " (need eps_xx, eps_yy, eps_zz, eps_yz, "
                                   "eps_xz, eps_xy: tensor components)");
          }
        for (std::size_t r = 0; r < table.rows(); ++r)
          {
            dem::Vector6d v;
            for (int b = 0; b < 6; ++b)
              {
                v[b]                    = table.number(r, slot[b]);
                const std::string &cell = table.text(r, slot[b]);
                if (!std::isfinite(v[b]))
                  throw io::CsvError(file,
                                     table.where(r, slot[b]) + ": '" + cell
                                       + "' is not a finite number");
                if (std::abs(v[b]) >= 0.1)
                  throw io::CsvError(file,
                                     table.where(r, slot[b]) + ": increment "
                                       + cell
                                       + " is not small (|eps| must stay "
                                         "below 0.1 per step)");
              }
            // Tensor components: the shears enter the symmetric tensor as
            // given.
            Eigen::Matrix3d e;
            e << v[0], v[5], v[4], //
              v[5], v[1], v[3],    //
              v[4], v[3], v[2];
            increments.push_back(e);
          }
      }
    catch (const io::CsvError &e)
      {
        input::reject_entry(entry, file, e.reason());
      }
    if (increments.empty())
      input::reject_entry(entry, file, "the file has no strain increments");
    return increments;
  }

  void
  declare_rve_cell_parameters(dealii::ParameterHandler &prm,
                              const std::string        &protocol)
  {
    prm.enter_subsection("Material");
    coupling::declare_particle_material(prm, coupling::material_1);
    prm.leave_subsection();

    declare_bonding_parameters(prm, BondedBodies::one_species);

    prm.enter_subsection("Packing");
    prm.declare_entry("Number of particles",
                      "200",
                      dealii::Patterns::Integer(2, 10000000),
                      "Spheres in the fully periodic cubic cell, in [2, 1e7].");
    prm.declare_entry("Size distribution",
                      "monodisperse",
                      dealii::Patterns::Selection(
                        "monodisperse|log-normal|quantiles"),
                      "monodisperse: every radius is Material/Radius; "
                      "log-normal: ln R normal with median Material/Radius, "
                      "Log-normal sigma and the radius cut-offs; quantiles: "
                      "a log-normal fitted to the volume quantiles x10, x50, "
                      "x90 (Giannis 2021 Table 1), sampled by number "
                      "(Hatch-Choate) between the diameter cut-offs.");
    input::declare_quantity(prm,
                            "Log-normal sigma",
                            "0.1",
                            input::non_negative(),
                            "-",
                            "Standard deviation of ln R (Size distribution = "
                            "log-normal).");
    input::declare_quantity(prm,
                            "Minimum radius",
                            "0",
                            input::non_negative(),
                            "m",
                            "Lower cut-off of the log-normal radii.");
    input::declare_quantity(prm,
                            "Maximum radius",
                            "1",
                            input::positive(),
                            "m",
                            "Upper cut-off of the log-normal radii.");
    input::declare_quantity(prm,
                            "x10",
                            "360e-6",
                            input::positive(),
                            "m",
                            "Volume (Q3) 10% diameter (Size distribution = "
                            "quantiles).");
    input::declare_quantity(prm,
                            "x50",
                            "440e-6",
                            input::positive(),
                            "m",
                            "Volume (Q3) median diameter.");
    input::declare_quantity(prm,
                            "x90",
                            "540e-6",
                            input::positive(),
                            "m",
                            "Volume (Q3) 90% diameter.");
    input::declare_quantity(
      prm,
      "Minimum diameter",
      "300e-6",
      input::non_negative(),
      "m",
      "Lower cut-off of the sampled diameters (quantiles).");
    input::declare_quantity(
      prm,
      "Maximum diameter",
      "600e-6",
      input::positive(),
      "m",
      "Upper cut-off of the sampled diameters (quantiles).");
    prm.declare_entry(
      "Protocol",
      protocol,
      dealii::Patterns::Selection("deposited|compressed-gas"),
      "How the starting packing is made. deposited: a fully periodic cell "
      "cut from a ballistic deposit (the die's packing algorithm, spheres "
      "touching without force, virgin, at the deposit's relative density "
      "rho_dep, 0.48-0.53 measured for 80-1000 equal spheres), compacted by "
      "uniaxial strain along the deposit's direction of growth (z; the "
      "axial direction of the tablet model for multiscale materials) with "
      "the Solver's loading (the bonded path by default: histories grow "
      "from the first resolved contact force on) to the Initial relative "
      "density; compax rve and compax database reject an Initial relative "
      "density below rho_dep (exit 2, naming rho_dep), while compax "
      "tablet's Multiscale materials (database and FE2 pool) start from "
      "the deposit itself when it is denser than asked (the tablet's fill). "
      "compressed-gas: spheres inserted at random at the "
      "Insertion density and compressed hydrostatically with frozen "
      "histories to the Initial relative density (virgin), the former "
      "default, for comparison. deposited is the default everywhere; a "
      "small deposited cell can give compax database a degenerate cap fit "
      "(40 spheres: negative Poisson's ratio and zero cap pressure; 200 "
      "spheres, the default, fit).");
    input::declare_quantity(
      prm,
      "Initial relative density",
      "0.55",
      input::open(0.0, 0.74),
      "-",
      "Solid fraction of the packing the path starts from. "
      "Protocol = deposited: at least the deposit's own "
      "density rho_dep (see Protocol); compressed-gas: any "
      "(above ~0.64 the gas packing is already loaded).");
    input::declare_quantity(
      prm,
      "Insertion density",
      "0.25",
      input::open(0.0, 0.38),
      "-",
      "Solid fraction at which the spheres are inserted at "
      "random before the gas is compressed (Protocol = "
      "compressed-gas).");
    input::declare_quantity(
      prm,
      "Verlet skin",
      "0.3",
      input::open(0.0, 2.0),
      "-",
      "Verlet skin of the contact list as a fraction of the "
      "median radius.");
    prm.declare_entry("Seed",
                      "1",
                      dealii::Patterns::Integer(0),
                      "Seed of the packing's random numbers (same seed, "
                      "same packing), >= 0.");
    prm.leave_subsection();
  }

  void
  declare_rve_solver_parameters(dealii::ParameterHandler &prm,
                                const std::string        &consolidation)
  {
    prm.enter_subsection("Solver");
    coupling::declare_equilibrium_tolerances(prm);
    input::declare_quantity(
      prm,
      "Jamming pressure",
      "0.5e6",
      input::non_negative(),
      "Pa",
      "Below this mean compressive stress -tr(sigma)/3 a step "
      "is relaxed at fixed internal variables (the loose cell has no "
      "stiffness for Newton), as Consolidation and Unjammed equilibrium "
      "say; 0: every step by Newton.");
    prm.declare_entry(
      "Consolidation",
      consolidation,
      dealii::Patterns::Selection("none|frozen-history"),
      "What happens below the Jamming pressure (as compax die's "
      "Protocol/Consolidation). none (the bonded path): a sub-step is "
      "relaxed at fixed internal variables (by default L-BFGS to the "
      "Solver tolerances, see Unjammed equilibrium), and that relaxed "
      "state is a converged state to which the history update of Eq. 13 "
      "applies; contact forces below 1e-2 x "
      "Jamming pressure on a mean cross-section pi R^2 (7.6e-4 N for R = "
      "220 um and 0.5 MPa) grow no plastic radius and no bridge (History "
      "update = resolved-forces); once a "
      "converged state carried the Jamming pressure the cell stays jammed "
      "(Newton for every later step, unloading included). frozen-history: "
      "the former shortcut, for comparison: a step that starts below the "
      "Jamming pressure relaxes with frozen (uncommitted) histories; Eq. 13 "
      "applies to Newton steps only.");
    prm.declare_entry(
      "Unjammed equilibrium",
      "balanced-lbfgs",
      dealii::Patterns::Selection(
        "relaxation|relaxation+newton|balanced-relaxation|balanced-lbfgs"),
      "Consolidation = none only (as compax die's Protocol/Unjammed "
      "equilibrium): the converged state of a step below the Jamming "
      "pressure. relaxation: the FIRE relaxation. relaxation+newton: the "
      "relaxation followed by the trust-region Newton to the Solver "
      "tolerances (from where the relaxation got to, converged or not; a "
      "step whose Newton fails is cut back). balanced-relaxation: the "
      "relaxation itself run to the Solver tolerances (or every net force "
      "below 1e-6 of a particle's share of the Jamming pressure) for as "
      "long as it keeps approaching them (as compax die's), else the step "
      "is cut back. balanced-lbfgs "
      "(default): the same, minimised by L-BFGS instead of FIRE. The last "
      "three balance loose states as tightly as jammed ones.");
    declare_history_update(prm,
                           "1e-2 x Jamming pressure on a mean cross-section "
                           "pi R^2");
    prm.leave_subsection();
  }

  void
  declare_rve_parameters(dealii::ParameterHandler &prm)
  {
    declare_rve_cell_parameters(prm);
    prm.enter_subsection("Strain path");
    prm.declare_entry("Path",
                      "uniaxial",
                      dealii::Patterns::Selection("uniaxial|hydrostatic|csv"),
                      "uniaxial: F = diag(1, 1, rho_0/rho), die-like "
                      "compaction along z in equal density steps; "
                      "hydrostatic: F = (rho_0/rho)^(1/3) I; csv: F <- (I + "
                      "eps) F for each row of the Strain increments file.");
    input::declare_quantity(
      prm,
      "Target relative density",
      "0.8",
      input::open(0.0, 1.0),
      "-",
      "Relative density at the end of loading (uniaxial, "
      "hydrostatic); above the Initial relative density.");
    prm.declare_entry("Loading steps",
                      "25",
                      dealii::Patterns::Integer(1, 100000),
                      "Equal density steps of loading (uniaxial, "
                      "hydrostatic; sub-steps are cut back automatically), in "
                      "[1, 100000].");
    prm.declare_entry("Unloading",
                      "true",
                      dealii::Patterns::Bool(),
                      "Unload along the same path after loading: uniaxial "
                      "until the axial stress sigma_zz, hydrostatic until the "
                      "mean stress vanishes; csv: the increments undone in "
                      "reverse order until the mean stress vanishes.");
    input::declare_quantity(prm,
                            "Unloading strain step",
                            "5e-4",
                            input::open(0.0, 0.1),
                            "-",
                            "Logarithmic strain per unloading step (eps_zz for "
                            "uniaxial, each normal strain for hydrostatic).");
    prm.declare_entry("Maximum unloading steps",
                      "500",
                      dealii::Patterns::Integer(1, 100000),
                      "Unloading stops after this many steps even if the "
                      "stress has not vanished, in [1, 100000].");
    prm.declare_entry("Strain increments file",
                      "",
                      dealii::Patterns::Anything(),
                      "Path = csv: a CSV file with a header naming the "
                      "columns eps_xx, eps_yy, eps_zz, eps_yz, eps_xz, eps_xy "
                      "(tensor components, not engineering shears) and one "
                      "small strain increment per row, applied to the "
                      "current configuration. A relative path is taken from "
                      "the folder of the .prm.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Tangent interval",
                      "1",
                      dealii::Patterns::Integer(0, 100000),
                      "Condensed and affine tangents and elastic moduli "
                      "(moduli.csv) every this many steps; also at the end of "
                      "loading and of the path. 0: only there.");
    prm.declare_entry("Finite-difference check interval",
                      "5",
                      dealii::Patterns::Integer(0, 100000),
                      "Compare the condensed tangent with central finite "
                      "differences of the cell (12 equilibrium solves, "
                      "histories frozen) every this many steps "
                      "(tangent_fd_error in moduli.csv), at a trial state "
                      "half a step further along the path equilibrated with "
                      "frozen histories: a converged state puts every "
                      "loading contact on the kink between its plastic and "
                      "unloading branches, where a central difference "
                      "approximates neither. 0: never.");
    input::declare_quantity(
      prm,
      "Finite-difference strain step",
      "1e-8",
      input::open(0.0, 1e-2),
      "-",
      "Strain perturbation h of the finite-difference tangent "
      "(small: a contact crossing a kink of its law within +-h "
      "spoils a central difference; 1e-6 gives ~5e-4 error "
      "on the default case, 1e-8 ~3e-7) "
      "(engineering shears).");
    input::declare_quantity(
      prm,
      "Finite-difference force tolerance",
      "1e-10",
      input::open(0.0, 1.0),
      "-",
      "Equilibrium force (and step) tolerance of the "
      "finite-difference solves; the stress error it leaves "
      "is divided by h.");
    prm.declare_entry("Snapshot interval",
                      "5",
                      dealii::Patterns::Integer(0, 100000),
                      "VTU snapshot of the particles (wrapped into the cell) "
                      "every this many steps, listed in snapshots.pvd; 0: "
                      "none.");
    prm.leave_subsection();

    prm.enter_subsection("Size study");
    prm.declare_entry("Cell sizes",
                      "",
                      dealii::Patterns::List(
                        dealii::Patterns::Integer(2, 10000000)),
                      "Particle counts of an RVE-size study (Giannis 2021 "
                      "Sec. 4.1): the same path for each cell, with the same "
                      "packing statistics and seeds Seed, Seed+1, ...; "
                      "writes rve_size_study.csv and the spread between "
                      "sizes. Empty: one run with Packing/Number of "
                      "particles.");
    prm.leave_subsection();

    prm.enter_subsection("Checkpoints");
    prm.declare_entry("Checkpoint interval",
                      "0",
                      dealii::Patterns::Integer(0, 100000),
                      "Write checkpoints/rve.h5 (cell state, rows so far) "
                      "every this many steps, atomically; 0: never. At a "
                      "checkpoint the run refreshes its contact list and "
                      "solver state, so a resumed run repeats the "
                      "uninterrupted one exactly.");
    prm.declare_entry("Stop after steps",
                      "0",
                      dealii::Patterns::Integer(0, 100000),
                      "Stop after this many steps with a checkpoint and "
                      "publish the output so far; 0: run to the end.");
    prm.declare_entry("Resume from",
                      "",
                      dealii::Patterns::Anything(),
                      "A checkpoints/rve.h5 (relative to the .prm) of an "
                      "earlier run with the same parameters (all but "
                      "Checkpoints, Size study and Solver/Maximum "
                      "iterations; the strain increments file by its "
                      "content): continue its path where the checkpoint "
                      "was taken (rve.csv and moduli.csv get the earlier "
                      "rows too; its snapshots are copied from the "
                      "checkpoint's run folder and must be there "
                      "unchanged). A damaged or foreign file, or one of "
                      "other parameters (named), is refused. Empty: start "
                      "afresh.");
    prm.leave_subsection();

    declare_rve_solver_parameters(prm);

    coupling::declare_contact_choice(
      prm,
      "bonded-elastoplastic: the bonded elasto-plastic law of Gonzalez 2018 "
      "(Eq. 4) with the Material and Bonding entries; elastic: elastic "
      "frictionless spheres without bonding, with Material's Young's "
      "modulus and Poisson's ratio only (moduli.csv then stays empty: the "
      "condensed tangent is that of the bonded law; the packing is made "
      "with the bonded law's elastic branch, virgin).",
      "hertz: independent contacts; nonlocal: the nonlocal contact "
      "formulation of Gonzalez & Cuitino 2012 (Algorithm 1 at every "
      "residual, contacts through lattice images included), a layer on an "
      "elastic law: Contact law = elastic (Hertz) or a registered law of "
      "elastic bodies without internal variables (hertz). Elastic cells are "
      "solved by a trust region on the frozen-angle Hessian with an "
      "exact-Jacobian Newton-Krylov finish, below Solver/Jamming pressure "
      "by FIRE with the local law alone.");
  }

  RveCell
  get_rve_cell(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    const dem::ElastoplasticMaterial material
      = coupling::get_particle_material(prm);
    const double omega  = coupling::get_surface_energy(prm);
    const double radius = coupling::get_particle_radius(prm);
    prm.leave_subsection();

    prm.enter_subsection("Bonding");
    const double K
      = prm.get_bool("Fracture toughness from energies")
          ? dem::fracture_toughness_from_energies(material,
                                                  omega,
                                                  material,
                                                  omega,
                                                  prm.get_double(
                                                    "Plastic dissipation"))
          : prm.get_double("Fracture toughness");
    RveCell s{dem::ContactModel(material,
                                K,
                                prm.get_double("Regularization parameter")),
              {},
              {}};
    prm.leave_subsection();

    prm.enter_subsection("Packing");
    s.packing.particle_count    = prm.get_integer("Number of particles");
    s.packing.relative_density  = prm.get_double("Initial relative density");
    s.packing.insertion_density = prm.get_double("Insertion density");
    s.packing.protocol          = prm.get("Protocol") == "compressed-gas"
                                    ? dem::PackingProtocol::compressed_gas
                                    : dem::PackingProtocol::deposited;
    s.packing.skin              = prm.get_double("Verlet skin");
    s.packing.seed = static_cast<std::uint64_t>(prm.get_integer("Seed"));
    const std::string distribution = prm.get("Size distribution");
    if (distribution == "monodisperse")
      {
        s.packing.sizes.median_radius = radius;
        s.size_description
          = "monodisperse, R = " + input::format_number(radius) + " m";
      }
    else if (distribution == "log-normal")
      {
        auto &d         = s.packing.sizes;
        d.median_radius = radius;
        d.log_sigma     = prm.get_double("Log-normal sigma");
        d.min_radius    = prm.get_double("Minimum radius");
        d.max_radius    = prm.get_double("Maximum radius");
        if (!(d.min_radius < d.max_radius))
          input::reject_entry("Packing/Minimum radius",
                              input::format_number(d.min_radius),
                              "must be below the Maximum radius ("
                                + input::format_number(d.max_radius) + " m)");
        if (!(d.min_radius <= radius && radius <= d.max_radius))
          input::reject_entry(
            "Material/Radius",
            input::format_number(radius),
            "the median radius must lie between the cut-offs");
        s.size_description
          = "log-normal, median R = " + input::format_number(radius)
            + " m, sigma = " + input::format_number(d.log_sigma);
      }
    else
      {
        const double x10 = prm.get_double("x10"), x50 = prm.get_double("x50"),
                     x90   = prm.get_double("x90");
        const double d_min = prm.get_double("Minimum diameter"),
                     d_max = prm.get_double("Maximum diameter");
        if (!(x10 < x50 && x50 < x90))
          input::reject_entry("Packing/x50",
                              input::format_number(x50),
                              "need x10 < x50 < x90");
        if (!(d_min < d_max))
          input::reject_entry("Packing/Maximum diameter",
                              input::format_number(d_max),
                              "must exceed the Minimum diameter "
                                + input::format_number(d_min));
        const auto fit  = dem::fit_volume_log_normal(x10, x50, x90);
        s.packing.sizes = dem::number_radius_distribution(fit, d_min, d_max);
        const double median = s.packing.sizes.median_radius;
        if (!(0.5 * d_min <= median && median <= 0.5 * d_max))
          input::reject_entry("Packing/Minimum diameter",
                              input::format_number(d_min),
                              "the fitted number median diameter "
                                + input::format_number(2 * median)
                                + " m lies outside the cut-offs");
        s.size_description = "fitted to x10/x50/x90, number median R = "
                             + input::format_number(median) + " m, sigma = "
                             + input::format_number(fit.log_sigma);
      }
    prm.leave_subsection();
    return s;
  }

  void
  reject_deposit_density(const dem::PeriodicPackingSpec &packing,
                         const double                    deposit,
                         const std::string              &prefix)
  {
    input::reject_entry(
      prefix + "Packing/Initial relative density",
      input::format_number(packing.relative_density),
      "lies below the relative density of the deposited cell ("
        + input::format_number(deposit) + " for these particles and seed "
        + std::to_string(packing.seed)
        + "), which Packing/Protocol = deposited can only compact: "
          "allowed ["
        + input::format_number(deposit)
        + ", 0.74), or Packing/Protocol = compressed-gas");
  }

  void
  check_deposit_density(const dem::PeriodicPackingSpec &packing,
                        const unsigned int              seeds,
                        const std::string              &prefix)
  {
    if (packing.protocol != dem::PackingProtocol::deposited)
      return;
    for (unsigned int k = 0; k < seeds; ++k)
      {
        dem::PeriodicPackingSpec p = packing;
        p.seed                     = packing.seed + k;
        const double deposit = dem::make_rve_deposit(p).relative_density();
        if (p.relative_density < deposit)
          reject_deposit_density(p, deposit, prefix);
      }
  }

  dem::RveLoadingOptions
  get_rve_loading_options(dealii::ParameterHandler &prm)
  {
    dem::RveLoadingOptions o;
    prm.enter_subsection("Solver");
    coupling::get_equilibrium_tolerances(prm, o.equilibrium);
    o.jamming_pressure = prm.get_double("Jamming pressure");
    o.consolidation    = prm.get("Consolidation") == "frozen-history"
                           ? dem::RveConsolidation::frozen_history
                           : dem::RveConsolidation::none;
    o.unjammed_equilibrium
      = dem::parse_unjammed_equilibrium(prm.get("Unjammed equilibrium"));
    o.resolved_history = coupling::get_resolved_history(prm);
    prm.leave_subsection();
    return o;
  }

  RveStudy
  get_rve_study(dealii::ParameterHandler &prm)
  {
    RveCell  cell = get_rve_cell(prm);
    RveStudy s(std::move(cell.model));
    s.packing          = cell.packing;
    s.size_description = cell.size_description;

    prm.enter_subsection("Strain path");
    const std::string path = prm.get("Path");
    s.path                 = path == "uniaxial"      ? RvePath::uniaxial
                             : path == "hydrostatic" ? RvePath::hydrostatic
                                                     : RvePath::increments;
    s.target_density       = prm.get_double("Target relative density");
    s.steps                = prm.get_integer("Loading steps");
    s.unload               = prm.get_bool("Unloading");
    s.unloading_step       = prm.get_double("Unloading strain step");
    s.max_unloading_steps  = prm.get_integer("Maximum unloading steps");
    s.csv_file             = prm.get("Strain increments file");
    prm.leave_subsection();
    if (s.path != RvePath::increments
        && s.target_density <= s.packing.relative_density)
      input::reject_entry("Strain path/Target relative density",
                          input::format_number(s.target_density),
                          "must exceed Packing/Initial relative density = "
                            + input::format_number(s.packing.relative_density));
    if (s.path == RvePath::increments)
      {
        if (s.csv_file.empty())
          input::reject_entry(
            "Strain path/Strain increments file",
            "(empty)",
            "Path = csv needs a CSV file of strain increments");
        s.increments = read_strain_increments(
          input::resolve_input_path(s.csv_file).string(),
          "Strain path/Strain increments file");
        s.steps = static_cast<int>(s.increments.size());
      }

    prm.enter_subsection("Output");
    s.tangent_interval   = prm.get_integer("Tangent interval");
    s.fd_interval        = prm.get_integer("Finite-difference check interval");
    s.fd_strain_step     = prm.get_double("Finite-difference strain step");
    s.fd_force_tolerance = prm.get_double("Finite-difference force tolerance");
    s.snapshot_interval  = prm.get_integer("Snapshot interval");
    prm.leave_subsection();

    prm.enter_subsection("Size study");
    const std::string cell_sizes = prm.get("Cell sizes");
    for (const auto &item :
         dealii::Utilities::split_string_list(cell_sizes, ','))
      s.cell_sizes.push_back(
        static_cast<std::size_t>(dealii::Utilities::string_to_int(item)));
    prm.leave_subsection();
    if (s.cell_sizes.size() == 1)
      input::reject_entry(
        "Size study/Cell sizes",
        std::to_string(s.cell_sizes.front()),
        "a size study needs at least two cell sizes (leave it "
        "empty for one run)");

    prm.enter_subsection("Checkpoints");
    s.checkpoint_interval = prm.get_integer("Checkpoint interval");
    s.stop_after          = prm.get_integer("Stop after steps");
    s.resume_from         = prm.get("Resume from");
    if (!s.resume_from.empty())
      s.resume_from = input::resolve_input_path(s.resume_from).string();
    prm.leave_subsection();
    s.resume_parameters = input::canonical_parameters(
      prm,
      {},
      {"Checkpoints", "Size study", "Solver/Maximum iterations"},
      {"Strain path/Strain increments file"});
    if (!s.cell_sizes.empty() && (!s.resume_from.empty() || s.stop_after > 0))
      input::reject_entry(
        "Size study/Cell sizes",
        cell_sizes,
        "a size study cannot be stopped or resumed (leave "
        "Checkpoints/Resume from empty and Stop after steps 0)");

    s.loading = get_rve_loading_options(prm);

    const coupling::ContactChoice contact = coupling::get_contact_choice(prm);
    coupling::apply_contact_choice(contact, s.model);
    if (coupling::solved_as_elastic_spheres(contact))
      {
        dem::NonlocalRveOptions e;
        const auto             &m = s.model.material(0);
        e.materials               = {{m.youngs_modulus, m.poisson_ratio}};
        e.nonlocal                = contact.formulation == "nonlocal";
        e.bed.local_laws = coupling::elastic_local_laws(contact, s.model);
        coupling::set_elastic_solver_tolerances(e, s.loading.equilibrium);
        e.jamming_pressure     = s.loading.jamming_pressure;
        e.fire_iterations      = s.loading.fire_iterations;
        e.fire_tolerance       = s.loading.fire_tolerance;
        e.force_floor_fraction = s.loading.force_floor_fraction;
        s.elastic              = e;
      }

    if (s.cell_sizes.empty())
      check_cell_width("Packing/Number of particles",
                       s.packing.particle_count,
                       s);
    else
      for (const std::size_t n : s.cell_sizes)
        check_cell_width("Size study/Cell sizes", n, s);
    return s;
  }
} // namespace compax::coupling

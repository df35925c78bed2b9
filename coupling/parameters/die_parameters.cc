#include "coupling/parameters/die_parameters.h"

#include "coupling/parameters/contact_parameters.h"
#include "coupling/parameters/equilibrium_parameters.h"
#include "coupling/parameters/material_parameters.h"
#include "dem/die/die_setup.h"
#include "input/canonical_parameters.h"
#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace compax::coupling
{
  namespace
  {
    /// Material 2 of Gonzalez 2018, Table 1 (R = 220 um).
    constexpr ParticleDefaults material_2_defaults{220e-6,
                                                   30e9,
                                                   0.25,
                                                   900e6,
                                                   2.0,
                                                   600.0};
  } // namespace

  void
  declare_die_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    declare_particle_material(prm, material_1);
    prm.leave_subsection();
    // A second species, used when Packing/Material fractions lists two
    // fractions (defaults: Material 2 of Gonzalez 2018, Table 1).
    prm.enter_subsection("Material 2");
    declare_particle_material(prm, material_2_defaults);
    prm.leave_subsection();

    declare_bonding_parameters(prm, BondedBodies::species_and_walls);

    prm.enter_subsection("Packing");
    prm.declare_entry("Number of particles",
                      "400",
                      dealii::Patterns::Integer(1, 10000000),
                      "Particles dropped by ballistic deposition "
                      "(Jullien & Meakin 1989), in [1, 1e7].");
    input::declare_quantity(prm,
                            "Die diameter",
                            "4e-3",
                            input::positive(),
                            "m",
                            "Diameter D of the rigid cylindrical die.");
    input::declare_quantity(prm,
                            "Log-normal sigma",
                            "0",
                            input::non_negative(),
                            "-",
                            "Standard deviation of ln R of a log-normal size "
                            "distribution with median the Material's Radius; 0 "
                            "for a monodisperse bed.");
    input::declare_quantity(prm,
                            "Minimum radius",
                            "0",
                            input::non_negative(),
                            "m",
                            "Lower cut-off of the log-normal distribution.");
    input::declare_quantity(prm,
                            "Maximum radius",
                            "1",
                            input::positive(),
                            "m",
                            "Upper cut-off of the log-normal distribution.");
    input::declare_quantity(
      prm,
      "Material fractions",
      "1",
      dealii::Patterns::List(dealii::Patterns::Double(0, 1), 1, 2),
      "-",
      "Number fractions of the particle species, summing to "
      "1: one value (Material only) or two (Material, "
      "Material 2; each particle draws its species at "
      "random with these probabilities). Both species must "
      "have the same Radius (one size distribution).");
    prm.declare_entry("Seed",
                      "1",
                      dealii::Patterns::Integer(0),
                      "Seed of the packing's random numbers (same seed, "
                      "same packing), >= 0.");
    prm.leave_subsection();

    prm.enter_subsection("Protocol");
    input::declare_quantity(
      prm,
      "Final relative density",
      "0.87",
      input::open(0.0, 1.0),
      "-",
      "In-die relative density at which compaction ends.");
    prm.declare_entry("Compaction steps",
                      "30",
                      dealii::Patterns::Integer(1, 100000),
                      "Equal density steps from the packing's density to "
                      "the final density (load steps are cut back "
                      "automatically when needed), in [1, 100000].");
    input::declare_quantity(
      prm,
      "Unloading points",
      "0.75, 0.79, 0.83, 0.87",
      dealii::Patterns::List(dealii::Patterns::Double(0, 1)),
      "-",
      "In-die relative densities rho_max at which an "
      "unloading branch starts from the compaction path "
      "(comma-separated, each in (0, 1), at most the final "
      "density; empty for none).");
    input::declare_quantity(
      prm,
      "Unloading step",
      "2e-3",
      input::open(0.0, 0.5),
      "-",
      "Upper-punch withdrawal per unloading step as a "
      "fraction of the punch gap at the unloading point.");
    prm.declare_entry("Minimum unloading steps",
                      "12",
                      dealii::Patterns::Integer(1, 100000),
                      "After the first unloading step the step is reduced, "
                      "if needed, so that the punch comes free in about this "
                      "many steps (extrapolated with the first step's "
                      "stiffness): the tablet's E and nu come from the "
                      "central third of the unloading curve. In [1, 100000].");
    prm.declare_entry("Eject",
                      "true",
                      dealii::Patterns::Bool(),
                      "Whether each unloaded compact is ejected (the die "
                      "wall is released in steps).");
    input::declare_quantity(prm,
                            "Die-wall friction coefficient",
                            "1",
                            input::non_negative(),
                            "-",
                            "Coulomb coefficient mu of the ejection pressure "
                            "mu F_radial / A_punch (Gonzalez 2018, Sec. 5.4).");
    input::declare_quantity(
      prm,
      "Ejection step",
      "2e-4",
      input::open(0.0, 0.1),
      "-",
      "Die-radius increase per ejection step, as a fraction "
      "of the die radius.");
    prm.declare_entry("Rerun branch from",
                      "",
                      dealii::Patterns::Anything(),
                      "Path of a branch checkpoint written by an earlier run "
                      "with the same Material, Material 2, Bonding, Packing "
                      "and Contact (OUTDIR/checkpoints/branch-<k>.h5): skip "
                      "packing and "
                      "compaction and rerun that unloading branch (unloading "
                      "and ejection) from the saved state, with this file's "
                      "other protocol and solver settings. Empty: run the "
                      "whole study.");
    prm.declare_entry("Checkpoint interval",
                      "10",
                      dealii::Patterns::Integer(0, 100000),
                      "Write checkpoints/compaction.h5 (bed, die.csv rows, "
                      "branches, fabric and histogram rows so far) every this "
                      "many compaction steps and at the end, replacing the "
                      "previous one atomically; 0: never. The load "
                      "stepper restarts after each checkpoint (no secant "
                      "predictor, full sub-step), as a run resumed from it "
                      "does, so that the resumed run retraces the "
                      "uninterrupted one; on the loose path this changes "
                      "which balanced state the bed reaches (1500 spheres "
                      "of Material 1: first 0.5 MPa at rho 0.6114 with "
                      "checkpoints every 10 steps, 0.6163 without; "
                      "doc/loose_regime.md). While "
                      "a run is in progress its output is staged in the "
                      "hidden folder .<OUTDIR>.partial-<pid> next to OUTDIR: "
                      "after a kill the checkpoint is there; after a stop "
                      "(exit 3 or Stop after compaction steps) it is in "
                      "OUTDIR/checkpoints. In [0, 100000].");
    prm.declare_entry("Stop after compaction steps",
                      "0",
                      dealii::Patterns::Integer(0, 100000),
                      "Stop after this many compaction steps (their "
                      "unloading branches included) with a checkpoint, and "
                      "publish the output so far, e.g. to split a long study "
                      "over several jobs; 0: run to the end. Counted from "
                      "the start of the study (also when resuming). A resumed "
                      "run equals the uninterrupted one exactly when it "
                      "stopped at a multiple of the Checkpoint interval.");
    prm.declare_entry("Resume from",
                      "",
                      dealii::Patterns::Anything(),
                      "A checkpoints/compaction.h5 written by an interrupted "
                      "or stopped run with the same parameters (all but "
                      "Final relative density, Compaction steps, Unloading "
                      "points, Checkpoint interval, Stop after compaction "
                      "steps and Solver/Maximum iterations; the checkpoint "
                      "names the first that differs): continue that run "
                      "where the checkpoint was taken, skipping packing and "
                      "the compaction done (die.csv, branches.csv, fabric.csv "
                      "and force_histograms.csv get the earlier rows from the "
                      "checkpoint; the earlier branches' snapshots and branch "
                      "checkpoints are copied from the checkpoint's run "
                      "folder, and must be there unchanged). Final relative "
                      "density may be raised; the targets done must be "
                      "unchanged. A damaged or foreign file is refused. "
                      "Empty: start afresh.");
    prm.declare_entry(
      "Consolidation",
      "none",
      dealii::Patterns::Selection("none|frozen-history"),
      "How the loose deposit reaches jamming. none (the bonded path): every "
      "compaction step from the deposit on ends in a converged state to "
      "which the history update of Eq. 13 applies (Gonzalez 2018, "
      "Algorithm 1), so bridges form from the first resolved contact force "
      "on. While the punches carry less than 0.5 MPa a step is relaxed at "
      "fixed internal variables (Newton has no stiffness along the "
      "mechanisms of an unjammed bed; Unjammed equilibrium says by which "
      "minimiser and to which tolerance: by default L-BFGS to the Solver "
      "tolerances); above, the trust-region Newton solves to the Solver "
      "tolerances. "
      "Contact forces below 1e-2 x 0.5 MPa on a mean cross-section pi R^2 "
      "(7.6e-4 N for R = 220 um) are not resolved: the coordination number "
      "counts the contacts above, and with History update = resolved-forces "
      "they grow no plastic radius. "
      "frozen-history: the former shortcut, for comparison: the bed is "
      "relaxed at fixed (virgin) internal variables, without plastic "
      "deformation or bridges, until the punch carries 0.5 MPa; Eq. 13 "
      "applies only from there on, and compaction targets below that "
      "density are skipped.");
    prm.declare_entry(
      "Unjammed equilibrium",
      "balanced-lbfgs",
      dealii::Patterns::Selection(
        "relaxation|relaxation+newton|balanced-relaxation|"
        "balanced-lbfgs|least-squares"),
      "Bonded path (Consolidation = none) only: the converged state of a "
      "step while the punches carry less than 0.5 MPa. relaxation: the FIRE "
      "relaxation at fixed internal variables, balanced to 1e-2 of the mean "
      "contact force or below the force resolution (fast, but it accepts "
      "force chains a balanced loose bed does not carry, and Eq. 13 grows "
      "their plastic radii and bridges). relaxation+newton: the "
      "relaxation is followed by the trust-region Newton to the Solver "
      "tolerances (from where the relaxation got to, converged or not; a "
      "step whose Newton fails is cut back); it crawls near the jamming "
      "onset. balanced-relaxation: the relaxation itself runs to the Solver "
      "tolerances (relative force tolerance, or every net force below "
      "1e-6 of a particle's share of 0.5 MPa) for as long as it keeps "
      "approaching them (its largest net force over the force it must fall "
      "below halves within every 2e5 FIRE iterations, at most 1e6), else "
      "the step is cut back: loose states balance as tightly as "
      "jammed ones, and it passes the jamming onset of the 6512-sphere "
      "beds where Newton's overlap-scale steps crawl. balanced-lbfgs "
      "(default): the same problem and tolerances, minimised by L-BFGS "
      "instead of FIRE (3.6x fewer residual evaluations and 7x less time "
      "to rho = 0.70 on the 6512-sphere Material 1 bed, 1.7x on 2000 "
      "spheres; see doc/loose_regime.md). least-squares: no "
      "relaxation; Gonzalez 2018 Algorithm 1 as printed, a trust region on "
      "the least-squares problem min |F|^2 whose step solves the "
      "Gauss-Newton model, converged when the step moves no particle "
      "farther than Solver/Step tolerance (Error = |s| < TOL1) or when "
      "balanced; on the loose beds measured (doc/loose_regime.md) "
      "contacts opening and closing hold the trust radius at the overlap "
      "scale and the solve ends when a rejection cuts it below TOL1, so "
      "its converged states may keep force chains (die.csv's residual "
      "shows the imbalance left). The loose steps crawl at that radius: "
      "raise Solver/Maximum iterations (2000 for the 1500-sphere beds of "
      "doc/loose_regime.md's measurement).");
    declare_history_update(prm,
                           "1e-2 x 0.5 MPa on a mean cross-section pi R^2, "
                           "7.6e-4 N for R = 220 um");
    prm.declare_entry(
      "Unjammed predictor",
      "secant",
      dealii::Patterns::Selection("secant|affine"),
      "Bonded path (Consolidation = none) only: where a step starts while "
      "the punches carry less than 0.5 MPa. A loose bed has many balanced "
      "states (every arrangement without overlaps), and the minimiser "
      "finds the one nearest to where the step starts, so this choice "
      "changes where the bed jams. secant (default): every particle moves "
      "on by its displacement of the last step, scaled to the punch's, "
      "like a momentum (the predictor of the jammed steps, where it only "
      "saves iterations). affine: the heights are mapped with the punch "
      "gap, the uniform strain from which the RVE's cell starts each step. "
      "Measured on 1500 spheres of Material 1 (doc/loose_regime.md): "
      "affine jams 0.005 earlier and runs 15 % faster.");
    prm.declare_entry(
      "Opening fallback",
      "at-first-failure",
      dealii::Patterns::Selection("at-first-failure|after-cutbacks"),
      "Bonded path (Consolidation = none) only: what a jammed bed does "
      "where Newton fails on a step that opens the punch gap (a compact "
      "without bridges coming apart on unloading, as with the Walton-Braun "
      "law or K_Ic = 0, whose network turns hypostatic before the punch "
      "carries nothing). at-first-failure (default): the balanced "
      "relaxation takes the sub-step at Newton's first failure. "
      "after-cutbacks: the step is cut back, and only the smallest "
      "sub-step is handed to the relaxation. Both stop at the same "
      "tolerances, the later opening sub-steps of the branch are relaxed "
      "without Newton, and the two may find different balanced states. "
      "Measured (doc/benchmarks.md): the Sec. 5 studies of both materials "
      "are the same to the bit; the 6512-sphere Walton-Braun bed unloads "
      "in 69 s instead of 138 s, punch pressures within 0.8 %.");
    prm.declare_entry("Maximum ejection steps",
                      "40",
                      dealii::Patterns::Integer(1, 100000),
                      "Ejection steps before the die wall is removed "
                      "altogether, in [1, 100000].");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    declare_equilibrium_tolerances(
      prm,
      "With the bonded law, net forces below this times the jamming "
      "pressure at which consolidation hands over to Newton (0.5 MPa) on a "
      "mean particle's cross-section pi R^2 count as converged too: a "
      "compact unloading towards a stress-free state has a vanishing mean "
      "contact force.");
    prm.leave_subsection();

    declare_contact_choice(
      prm,
      "bonded-elastoplastic: the bonded elasto-plastic law of Gonzalez 2018 "
      "(Eq. 4) with the Material and Bonding entries; elastic: elastic "
      "frictionless spheres without bonding, with the Young's modulus and "
      "Poisson's ratio of Material (and Material 2) only (the plastic and "
      "Bonding entries are not used; bonding surface and bonds are 0).",
      "hertz: independent contacts (local laws); nonlocal: the nonlocal "
      "contact formulation of Gonzalez & Cuitino 2012 (Eqs. 9, 10, "
      "Algorithm 1: the deformation of a particle by all its contact forces "
      "enters each contact), a layer on an elastic law: Contact law = "
      "elastic (Hertz) or a registered law of elastic bodies without "
      "internal variables (hertz). With Contact law = elastic, or the "
      "nonlocal formulation, the equilibria are solved by a trust region on "
      "the frozen-angle Hessian with an exact-Jacobian Newton-Krylov finish "
      "(consolidation with the local law alone), for both formulations.");
  }

  DieInput
  get_die_input(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Packing");
    std::vector<double> fractions
      = input::get_real_list(prm, "Material fractions");
    prm.leave_subsection();
    {
      double sum = 0.0;
      for (const double f : fractions)
        sum += f;
      std::ostringstream list;
      for (std::size_t k = 0; k < fractions.size(); ++k)
        list << (k ? ", " : "") << input::format_number(fractions[k]);
      if (std::abs(sum - 1.0) > 1e-9)
        input::reject_entry("Packing/Material fractions",
                            list.str(),
                            "the number fractions must sum to 1 (they sum to "
                              + input::format_number(sum) + ")");
    }
    const std::size_t n_materials = fractions.size();

    std::vector<dem::ElastoplasticMaterial> materials;
    std::vector<double>                     omegas;
    double                                  radius = 0.0;
    for (std::size_t a = 0; a < n_materials; ++a)
      {
        const std::string name = a == 0 ? "Material" : "Material 2";
        prm.enter_subsection(name);
        materials.push_back(get_particle_material(prm));
        omegas.push_back(get_surface_energy(prm));
        const double R = get_particle_radius(prm);
        prm.leave_subsection();
        if (a == 0)
          radius = R;
        else if (R != radius)
          input::reject_entry(name + "/Radius",
                              input::format_number(R),
                              "must equal Material/Radius = "
                                + input::format_number(radius)
                                + " m: the packing draws every radius from one "
                                  "size distribution");
      }

    prm.enter_subsection("Bonding");
    const double G_p = prm.get_double("Plastic dissipation");
    std::vector<std::vector<double>> toughness(n_materials,
                                               std::vector<double>(n_materials,
                                                                   0.0));
    const bool from_energies = prm.get_bool("Fracture toughness from energies");
    for (std::size_t a = 0; a < n_materials; ++a)
      for (std::size_t b = a; b < n_materials; ++b)
        {
          double K;
          if (from_energies)
            K = dem::fracture_toughness_from_energies(
              materials[a], omegas[a], materials[b], omegas[b], G_p);
          else
            K = prm.get_double(a != b   ? "Cross fracture toughness"
                               : a == 0 ? "Fracture toughness"
                                        : "Fracture toughness 2");
          toughness[a][b] = toughness[b][a] = K;
        }
    dem::ContactModel model(materials,
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
    // One species draws no material numbers (same packing as before).
    if (n_materials > 1)
      deposition.material_fractions = fractions;
    if (deposition.die_diameter <= 4 * radius)
      input::reject_entry(
        "Packing/Die diameter",
        input::format_number(deposition.die_diameter),
        "the die must be wider than two particle diameters (> "
          + input::format_number(4 * radius) + " m)");
    if (deposition.sizes.log_sigma > 0)
      {
        const auto  &sizes = deposition.sizes;
        const double sigma = sizes.log_sigma;
        if (sizes.min_radius >= sizes.max_radius)
          input::reject_entry("Packing/Minimum radius",
                              input::format_number(sizes.min_radius),
                              "must be below the Maximum radius ("
                                + input::format_number(sizes.max_radius)
                                + " m)");
        // The share of log-normal draws inside the cut-offs (rejection
        // sampling needs a reasonable one).
        const auto cdf = [&](const double r) {
          return r <= 0 ? 0.0
                        : 0.5
                            * std::erfc(-std::log(r / radius)
                                        / (sigma * std::sqrt(2.0)));
        };
        const double accepted = cdf(sizes.max_radius) - cdf(sizes.min_radius);
        if (!(accepted >= 1e-3))
          input::reject_entry(
            "Packing/Minimum radius",
            input::format_number(sizes.min_radius),
            "the cut-offs [" + input::format_number(sizes.min_radius) + ", "
              + input::format_number(sizes.max_radius)
              + "] m keep only a fraction " + input::format_number(accepted)
              + " of the log-normal radii around the median "
              + input::format_number(radius) + " m (Log-normal sigma = "
              + input::format_number(sigma) + "); widen them");
        if (4.0 * sizes.largest() >= deposition.die_diameter)
          input::reject_entry(
            "Packing/Log-normal sigma",
            input::format_number(sigma),
            "the largest radius the packing may draw, min(Maximum "
            "radius, Radius exp(6 sigma)) = "
              + input::format_number(sizes.largest())
              + " m, must be below a quarter of the die diameter ("
              + input::format_number(deposition.die_diameter / 4)
              + " m): lower the sigma or set Packing/Maximum "
                "radius");
      }
    prm.leave_subsection();

    prm.enter_subsection("Protocol");
    dem::DieProtocol protocol;
    const double     final_density = prm.get_double("Final relative density");
    const int        steps         = prm.get_integer("Compaction steps");
    protocol.unloading_points = input::get_real_list(prm, "Unloading points");
    const std::string rerun   = prm.get("Rerun branch from");
    for (const double u : protocol.unloading_points)
      if (rerun.empty() && (u <= 0.0 || u > final_density))
        input::reject_entry(
          "Protocol/Unloading points",
          input::format_number(u),
          "each unloading point must lie in (0, Final relative "
          "density = "
            + input::format_number(final_density) + "]");
    protocol.unloading_step      = prm.get_double("Unloading step");
    protocol.min_unloading_steps = prm.get_integer("Minimum unloading steps");
    protocol.eject               = prm.get_bool("Eject");
    protocol.friction_coefficient
      = prm.get_double("Die-wall friction coefficient");
    protocol.ejection_step      = prm.get_double("Ejection step");
    protocol.max_ejection_steps = prm.get_integer("Maximum ejection steps");
    protocol.consolidate        = prm.get("Consolidation") == "frozen-history";
    protocol.unjammed_equilibrium
      = dem::parse_unjammed_equilibrium(prm.get("Unjammed equilibrium"));
    protocol.resolved_history = get_resolved_history(prm);
    protocol.secant_predictor_unjammed
      = prm.get("Unjammed predictor") == "secant";
    protocol.relax_opening_at_first_failure
      = prm.get("Opening fallback") == "at-first-failure";
    protocol.checkpoint_interval = prm.get_integer("Checkpoint interval");
    protocol.stop_after      = prm.get_integer("Stop after compaction steps");
    const std::string resume = prm.get("Resume from");
    if (!resume.empty() && !rerun.empty())
      input::reject_entry("Protocol/Resume from",
                          resume,
                          "cannot be combined with Rerun branch from");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    dem::EquilibriumOptions equilibrium;
    get_equilibrium_tolerances(prm, equilibrium);
    prm.leave_subsection();

    const ContactChoice contact = get_contact_choice(prm);
    apply_contact_choice(contact, model);
    if (solved_as_elastic_spheres(contact))
      {
        dem::ElasticDieOptions elastic;
        for (const auto &m : materials)
          elastic.materials.push_back({m.youngs_modulus, m.poisson_ratio});
        elastic.nonlocal       = contact.formulation == "nonlocal";
        elastic.bed.local_laws = elastic_local_laws(contact, model);
        set_elastic_solver_tolerances(elastic, equilibrium);
        protocol.elastic = elastic;
      }

    // A resumed run continues the checkpoint's compaction path: every entry
    // but those that only say where it stops, how often it checkpoints and
    // where it resumes from must match (the compaction targets done are
    // compared on their own, so the final density may be raised; a run
    // that stopped without convergence may resume with more iterations).
    const std::string resume_parameters
      = input::canonical_parameters(prm,
                                    {},
                                    {"Protocol/Final relative density",
                                     "Protocol/Compaction steps",
                                     "Protocol/Unloading points",
                                     "Protocol/Rerun branch from",
                                     "Protocol/Checkpoint interval",
                                     "Protocol/Stop after compaction steps",
                                     "Protocol/Resume from",
                                     "Solver/Maximum iterations"});
    const std::string state_parameters = input::canonical_parameters(
      prm,
      with_registered_law_subsections(
        {"Material", "Material 2", "Bonding", "Packing", "Contact"}));
    return {model,
            {deposition, protocol, equilibrium, final_density, steps},
            rerun,
            resume,
            resume_parameters,
            state_parameters};
  }

  void
  reject_final_density(const dem::DieStudyOptions &study,
                       const double                packing_density)
  {
    input::reject_entry("Protocol/Final relative density",
                        input::format_number(study.final_density),
                        "must exceed the packing's relative density "
                          + input::format_number(packing_density));
  }

  void
  set_compaction_targets(dem::DieStudyOptions &study, const double rho_0)
  {
    study.protocol.compaction_targets = naming_final_density(study, [&] {
      return dem::die_compaction_targets(rho_0,
                                         study.final_density,
                                         study.compaction_steps);
    });
  }
} // namespace compax::coupling

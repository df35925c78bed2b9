#include "coupling/parameters/database_parameters.h"

#include "input/canonical_parameters.h"
#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"

namespace compax::coupling
{

  void
  declare_database_paths(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Paths");
    input::declare_quantity(prm,
                            "Final relative density",
                            "0.85",
                            input::open(0.0, 1.0),
                            "-",
                            "Uniaxial compaction stops here.");
    input::declare_quantity(prm,
                            "Compaction strain step",
                            "0.01",
                            input::open(0.0, 0.1),
                            "-",
                            "Axial logarithmic strain per compaction step.");
    prm.declare_entry("Branch densities",
                      "0.70, 0.75, 0.80, 0.85",
                      dealii::Patterns::List(dealii::Patterns::Double(0, 1), 2),
                      "Relative densities [-] at which the path "
                      "branches into unloading and shear probes: "
                      "increasing, above the initial and at most the "
                      "final density; one DPC table row each.");
    input::declare_quantity(prm,
                            "Shear strain",
                            "0.04",
                            input::open(0.0, 0.5),
                            "-",
                            "Engineering shear strain gamma_xz of each probe.");
    prm.declare_entry("Shear steps",
                      "20",
                      dealii::Patterns::Integer(2, 10000),
                      "Steps of each shear probe, in [2, 1e4]; the "
                      "second half gives the failure state.");
    input::declare_quantity(prm,
                            "Confinement strain",
                            "0.004",
                            input::open(0.0, 0.1),
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
    input::declare_quantity(prm,
                            "Radial strain",
                            "0.02",
                            input::open(0.0, 0.2),
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

  DatabaseSetup
  get_database_setup(dealii::ParameterHandler &prm, const std::string &where)
  {
    DatabaseSetup study{get_rve_cell(prm), {}};
    auto         &spec = study.spec;
    spec.packing       = study.cell.packing;
    spec.loading       = get_rve_loading_options(prm);
    prm.enter_subsection("Paths");
    spec.final_density      = prm.get_double("Final relative density");
    spec.strain_step        = prm.get_double("Compaction strain step");
    spec.branch_densities   = input::get_real_list(prm, "Branch densities");
    const std::string list  = prm.get("Branch densities");
    spec.shear_strain       = prm.get_double("Shear strain");
    spec.shear_steps        = prm.get_integer("Shear steps");
    spec.confinement_strain = prm.get_double("Confinement strain");
    spec.radial_ratios      = input::get_real_list(prm, "Radial strain ratios");
    spec.radial_strain      = prm.get_double("Radial strain");
    spec.radial_steps       = prm.get_integer("Radial steps");
    prm.leave_subsection();

    if (spec.branch_densities.size() < 2)
      input::reject_entry(
        where + "Paths/Branch densities",
        list,
        "a density-dependent cap needs at least two branches");
    for (std::size_t k = 0; k < spec.branch_densities.size(); ++k)
      {
        const double rho = spec.branch_densities[k];
        if (!(rho > spec.packing.relative_density && rho <= spec.final_density)
            || (k > 0 && !(rho > spec.branch_densities[k - 1])))
          input::reject_entry(
            where + "Paths/Branch densities",
            list,
            "increasing densities in (Packing/Initial relative "
            "density, Paths/Final relative density] = ("
              + input::format_number(spec.packing.relative_density) + ", "
              + input::format_number(spec.final_density) + "]");
      }
    return study;
  }

  void
  declare_database_run_options(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoints");
    prm.declare_entry("Stop after branches",
                      "0",
                      dealii::Patterns::Integer(0, 1000),
                      "Stop after this many completed branches (with "
                      "checkpoints/database.h5) and publish the rows so "
                      "far; 0: run to the end. After every branch the "
                      "run writes checkpoints/database.h5 (rows, branches "
                      "and the compaction cell) and refreshes its contact "
                      "list and solver state, so a resumed run repeats "
                      "the uninterrupted one exactly.");
    prm.declare_entry("Resume from",
                      "",
                      dealii::Patterns::Anything(),
                      "A checkpoints/database.h5 (relative to the .prm) "
                      "of an earlier run with the same parameters (all "
                      "but Checkpoints and Validation; the first that "
                      "differs is named): continue after its last "
                      "completed branch. A damaged or foreign file is "
                      "refused. Empty: start afresh.");
    prm.leave_subsection();
    prm.enter_subsection("Validation");
    prm.declare_entry("Held-out packing",
                      "true",
                      dealii::Patterns::Bool(),
                      "Also run every path on a second packing (Packing/"
                      "Seed + 1), not used in the fit: validation.csv "
                      "then holds the fitted law's error on that packing "
                      "and the packing-to-packing scatter of the RVE "
                      "itself (the yardstick of the law's error). "
                      "Doubles the run time.");
    prm.leave_subsection();
  }

  DatabaseRunOptions
  get_database_run_options(dealii::ParameterHandler &prm)
  {
    DatabaseRunOptions o;
    prm.enter_subsection("Checkpoints");
    o.stop_after_branches = prm.get_integer("Stop after branches");
    o.resume_from         = prm.get("Resume from");
    prm.leave_subsection();
    prm.enter_subsection("Validation");
    o.held_out_packing = prm.get_bool("Held-out packing");
    prm.leave_subsection();
    if (!o.resume_from.empty())
      o.resume_from = input::resolve_input_path(o.resume_from).string();
    return o;
  }

  std::string
  database_fingerprint(const dealii::ParameterHandler &prm)
  {
    return input::canonical_parameters(prm, {}, {"Checkpoints", "Validation"});
  }
} // namespace compax::coupling

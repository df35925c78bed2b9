#include "coupling/tablet_parameters.h"

#include "coupling/tablet_checkpoint.h"

#include "input/canonical_parameters.h"
#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"

#include <deal.II/base/utilities.h>
#include <deal.II/grid/tria.h>

#include <filesystem>
#include <string>
#include <vector>

namespace compax::coupling
{
  namespace
  {
    using dealii::Patterns::Bool;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;

    /// The mesh file @p entry names: absolute, or relative to the working
    /// folder or to the parameter file's folder.
    std::filesystem::path
    find_mesh_file(const std::string &entry)
    {
      namespace fs = std::filesystem;
      const fs::path        path(entry);
      std::vector<fs::path> candidates{path};
      if (path.is_relative())
        {
          const fs::path folder = input::parameter_file_directory();
          if (!folder.empty())
            candidates.push_back(folder / path);
        }
      for (const auto &candidate : candidates)
        if (fs::is_regular_file(candidate))
          return fs::absolute(candidate).lexically_normal();
      for (const auto &candidate : candidates)
        if (fs::is_directory(candidate))
          input::reject_entry(
            "Geometry/Mesh file",
            entry,
            "is a folder ("
              + fs::absolute(candidate).lexically_normal().string()
              + "), not a Gmsh .msh file");
      std::string where = "no such file";
      if (path.is_relative())
        {
          where += " in the working folder " + fs::current_path().string();
          if (candidates.size() > 1)
            where += " or beside the parameter file, in "
                     + fs::absolute(candidates[1].parent_path()).string();
        }
      input::reject_entry("Geometry/Mesh file", entry, where);
    }

    /// Bad input of Output/Resume from, for the reason @p e gives.
    [[noreturn]] void
    reject_resume(const TabletSetup &s, const TabletResumeError &e)
    {
      input::reject_entry("Output/Resume from",
                          s.output.resume_from.string(),
                          e.what());
    }
  } // namespace

  void
  declare_tablet_parameters(dealii::ParameterHandler    &prm,
                            const fem::MaterialRegistry &materials)
  {
    prm.enter_subsection("Geometry");
    input::declare_quantity(
      prm,
      "Die diameter",
      "10e-3",
      input::positive(),
      "m",
      "Inner diameter D of the cylindrical die (flat-faced "
      "punches of the same diameter).");
    input::declare_quantity(
      prm,
      "Fill height",
      "7e-3",
      input::positive(),
      "m",
      "Height of the powder column as filled; the die is "
      "filled to its top, so this is also the die-top height "
      "above the lower punch. Under a concave punch: the "
      "height at the die wall (the powder also fills the "
      "cup).");
    input::declare_quantity(
      prm,
      "Cup depth",
      "0",
      input::non_negative(),
      "m",
      "Depth h_c of the spherical cup of a concave upper "
      "punch (the tablet is h_c thicker on the axis than at "
      "the die wall); 0: flat-faced punch.");
    input::declare_quantity(
      prm,
      "Cup radius of curvature",
      "16e-3",
      input::positive(),
      "m",
      "Radius of curvature R_c of the cup; the cup edge "
      "radius sqrt(2 R_c h_c - h_c^2) must not exceed D/2 "
      "(the rest of the face is a flat land). Used when Cup "
      "depth > 0.");
    prm.declare_entry(
      "Mesh file",
      "",
      dealii::Patterns::Anything(),
      "Gmsh .msh file of the compact (ASCII; r-z quadrilaterals for the "
      "axisymmetric model, hexahedra of the quarter cylinder for "
      "quarter-3d) with physical ids axis 0, die wall 1, lower punch 2 "
      "(z = 0), upper punch 3 (flat or the cup of Cup depth and Cup radius "
      "of curvature, its land at the top of the die wall) and, in 3-D, the "
      "symmetry planes x = 0: 4, y = 0: 5, e.g. meshes/"
      "concave_punch_rz.msh. A relative path is looked up from the working "
      "folder, then from the folder of the parameter file. The mesh then "
      "sets Die diameter and Fill height (those entries and Radial cells "
      "are ignored). Empty: the built-in mesh. Unit: file path.");
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    prm.declare_entry("Model",
                      "axisymmetric",
                      Selection("axisymmetric|quarter-3d"),
                      "axisymmetric: r-z model with hoop terms (default); "
                      "quarter-3d: quarter cylinder with symmetry planes. "
                      "Unit: none.");
    input::declare_quantity(
      prm,
      "Radial cells",
      "8",
      Integer(1, 256),
      "-",
      "Cells across the radius of the coarse r-z mesh (the "
      "axial count makes cells square). Ignored by "
      "quarter-3d.");
    input::declare_quantity(prm,
                            "Refinements",
                            "0",
                            Integer(0, 6),
                            "-",
                            "Global refinements of the coarse mesh.");
    input::declare_quantity(prm,
                            "Polynomial degree",
                            "1",
                            Integer(1, 3),
                            "-",
                            "Degree of the displacement finite element.");
    prm.leave_subsection();

    prm.enter_subsection("Material");
    prm.declare_entry("Model",
                      "drucker-prager-cap",
                      Selection(materials.selection()),
                      "Constitutive law of the compact: "
                        + materials.documentation() + ". Unit: none.");
    input::declare_quantity(prm,
                            "Initial relative density",
                            "0.5",
                            input::open(0.0, 1.0),
                            "-",
                            "Relative density of the powder as filled.");
    materials.declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Die");
    input::declare_quantity(prm,
                            "Wall friction coefficient",
                            "0.25",
                            input::non_negative(),
                            "-",
                            "Coulomb friction coefficient mu between compact "
                            "and die wall (punch faces are frictionless).");
    prm.declare_entry("Wall friction table",
                      "",
                      dealii::Patterns::Anything(),
                      "Friction coefficient as a function of the relative "
                      "density at the wall, as 'density:mu' pairs in "
                      "increasing density, e.g. '0.5:0.4, 0.9:0.2' "
                      "(linear in between, constant beyond); empty: the "
                      "constant Wall friction coefficient. Unit: -:-.");
    input::declare_quantity(
      prm,
      "Entry taper length",
      "0",
      input::non_negative(),
      "m",
      "Length below the die top over which the bore widens "
      "(entry chamfer); the tablet then leaves the wall "
      "gradually during ejection. 0: sharp die top.");
    input::declare_quantity(prm,
                            "Entry taper opening",
                            "20e-6",
                            input::non_negative(),
                            "m",
                            "Radial widening of the bore at the die top.");
    input::declare_quantity(
      prm,
      "Penalty factor",
      "100",
      input::positive(),
      "-",
      "Contact penalty = factor x largest current Young's "
      "modulus / smallest cell size; penetration is about "
      "pressure x cell size / (factor E).");
    input::declare_quantity(
      prm,
      "Tangential penalty ratio",
      "0.1",
      input::positive(),
      "-",
      "Stick stiffness of the wall friction as a multiple "
      "of the normal penalty.");
    prm.leave_subsection();

    prm.enter_subsection("Process");
    input::declare_quantity(prm,
                            "Compaction displacement",
                            "3.11e-3",
                            input::positive(),
                            "m",
                            "Upper punch travel into the die (default: from "
                            "density 0.5 to 0.9 for a 7 mm fill).");
    input::declare_quantity(
      prm,
      "Unloading displacement",
      "0.3e-3",
      input::non_negative(),
      "m",
      "Upper punch withdrawal after compaction (more than "
      "the elastic springback, so the punch separates).");
    input::declare_quantity(
      prm,
      "Ejection displacement",
      "7.2e-3",
      input::non_negative(),
      "m",
      "Lower punch travel during ejection; beyond the fill "
      "height the tablet has left the die.");
    input::declare_quantity(prm,
                            "Compaction steps",
                            "240",
                            Integer(1, 100000),
                            "-",
                            "Load steps of the compaction stage.");
    input::declare_quantity(prm,
                            "Unloading steps",
                            "40",
                            Integer(0, 100000),
                            "-",
                            "Load steps of the unloading stage (0: none; then "
                            "Ejection steps must be 0 too).");
    input::declare_quantity(
      prm,
      "Ejection steps",
      "40",
      Integer(0, 100000),
      "-",
      "Load steps of the ejection stage (0: no ejection).");
    input::declare_quantity(
      prm,
      "Punch speed",
      "0.05",
      input::positive(),
      "m/s",
      "Punch speed that turns travel into the time column "
      "(the model is quasi-static).");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    input::declare_quantity(prm,
                            "Tolerance",
                            "1e-8",
                            input::open(0.0, 1.0),
                            "-",
                            "Newton tolerance on the residual relative to the "
                            "internal and contact forces (multiscale-fe2: at "
                            "least Multiscale/FE2 stress resolution).");
    input::declare_quantity(prm,
                            "Max iterations",
                            "30",
                            Integer(1, 1000),
                            "-",
                            "Newton iterations per load increment.");
    input::declare_quantity(prm,
                            "Max step cuts",
                            "8",
                            Integer(0, 30),
                            "-",
                            "Times a load step may be halved before the run "
                            "stops without convergence.");
    prm.declare_entry("Linear solver",
                      "direct",
                      Selection("direct|gmres-amg"),
                      "Newton systems: direct (Trilinos Amesos KLU, robust; "
                      "the matrix is gathered on one rank) or gmres-amg "
                      "(GMRES with algebraic multigrid, for large 3-D "
                      "meshes and many ranks; falls back to direct when it "
                      "fails). Unit: none.");
    prm.declare_entry("Print Newton residuals",
                      "false",
                      Bool(),
                      "Print every Newton residual (for diagnosing a "
                      "run that does not converge). Unit: none.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    input::declare_quantity(
      prm,
      "Field interval",
      "20",
      Integer(1, 100000),
      "-",
      "Write the PVD/VTU fields every this many steps (and "
      "at the end of every stage).");
    prm.declare_entry("Write fields",
                      "true",
                      Bool(),
                      "Write PVD/VTU fields. Unit: none.");
    prm.declare_entry("Write HDF5",
                      "true",
                      Bool(),
                      "With Write fields: also write the fields as "
                      "tablet_NNNN.h5 (parallel HDF5) listed by "
                      "tablet.xdmf, for ParaView or VisIt. Unit: none.");
    input::declare_quantity(
      prm,
      "Checkpoint interval",
      "50",
      Integer(0, 100000),
      "-",
      "Write a checkpoint (folder 'checkpoint' in the "
      "output) every this many steps and when a step does "
      "not converge; 0: none.");
    prm.declare_entry("Resume from",
                      "",
                      dealii::Patterns::Anything(),
                      "Output folder of an earlier run with the same "
                      "parameters (all but Checkpoint interval and the "
                      "Solver's Max iterations, Max step cuts, Linear "
                      "solver and Print Newton residuals; mesh and DPC "
                      "table files by their content) and number of MPI "
                      "ranks: continue its cycle from its checkpoint "
                      "(checkpoint/tablet.h5, which lists the solver "
                      "states with their hashes; its rows and fields are "
                      "copied into the new output). A damaged or foreign "
                      "checkpoint, or one of other parameters (named), is "
                      "refused. Empty: start afresh. Unit: folder path.");
    prm.leave_subsection();
  }

  TabletSetup
  parse_tablet_parameters(dealii::ParameterHandler    &prm,
                          const fem::MaterialRegistry &materials)
  {
    TabletSetup s;
    prm.enter_subsection("Geometry");
    s.solver.geometry.die_diameter = prm.get_double("Die diameter");
    s.solver.geometry.fill_height  = prm.get_double("Fill height");
    if (prm.get_double("Cup depth") > 0.0)
      {
        s.solver.geometry.upper_punch.cup_depth = prm.get_double("Cup depth");
        s.solver.geometry.upper_punch.cup_radius
          = prm.get_double("Cup radius of curvature");
      }
    const std::string mesh_entry = prm.get("Mesh file");
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    s.three_d                        = prm.get("Model") == "quarter-3d";
    s.solver.geometry.n_radial_cells = prm.get_integer("Radial cells");
    s.solver.refinements             = prm.get_integer("Refinements");
    s.solver.degree                  = prm.get_integer("Polynomial degree");
    prm.leave_subsection();

    if (!mesh_entry.empty())
      {
        const std::filesystem::path file = find_mesh_file(mesh_entry);
        s.solver.geometry.mesh_file      = file.string();
        try
          {
            // Read once here, so that a bad file is bad input before any
            // output exists; the solver reads it again.
            if (s.three_d)
              {
                dealii::Triangulation<3> tria;
                fem::read_compact_mesh(tria, s.solver.geometry);
              }
            else
              {
                dealii::Triangulation<2> tria;
                fem::read_compact_mesh(tria, s.solver.geometry);
              }
          }
        catch (const std::exception &e)
          {
            input::reject_entry("Geometry/Mesh file",
                                mesh_entry,
                                std::string(e.what())
                                  + (s.three_d
                                       ? " (Mesh/Model = quarter-3d)"
                                       : " (Mesh/Model = axisymmetric)"));
          }
        // The parameters written with the results name the file that
        // was used, from anywhere.
        prm.enter_subsection("Geometry");
        prm.set("Mesh file", file.string());
        prm.leave_subsection();
      }
    else
      try
        {
          s.solver.geometry.upper_punch.validate(s.solver.geometry.radius());
        }
      catch (const std::exception &e)
        {
          input::reject_entry("Cup depth",
                              input::format_number(
                                s.solver.geometry.upper_punch.cup_depth),
                              e.what());
        }

    prm.enter_subsection("Material");
    s.solver.initial_relative_density
      = prm.get_double("Initial relative density");
    const fem::RegisteredMaterial &model = materials.find(prm.get("Model"));
    if (model.create)
      try
        {
          s.material = model.create(prm);
        }
      catch (const input::InputError &)
        {
          prm.leave_subsection();
          throw;
        }
    else
      s.deferred_material = model.name;
    prm.leave_subsection();

    prm.enter_subsection("Die");
    s.solver.wall_friction  = prm.get_double("Wall friction coefficient");
    s.solver.penalty_factor = prm.get_double("Penalty factor");
    {
      const std::string table = prm.get("Wall friction table");
      for (const std::string &pair :
           dealii::Utilities::split_string_list(table, ','))
        {
          const auto parts = dealii::Utilities::split_string_list(pair, ':');
          double     rho = -1.0, mu = -1.0;
          try
            {
              if (parts.size() == 2)
                {
                  rho = std::stod(parts[0]);
                  mu  = std::stod(parts[1]);
                }
            }
          catch (const std::exception &)
            {
              rho = -1.0;
            }
          if (!(rho > 0.0 && rho <= 1.0 && mu >= 0.0)
              || (!s.solver.wall_friction_table.empty()
                  && !(rho > s.solver.wall_friction_table.back().first)))
            {
              prm.leave_subsection();
              input::reject_entry("Wall friction table",
                                  table,
                                  "expected 'density:mu' pairs with densities "
                                  "increasing in (0, 1] and mu >= 0");
            }
          s.solver.wall_friction_table.emplace_back(rho, mu);
        }
    }
    s.solver.die_top_taper_length  = prm.get_double("Entry taper length");
    s.solver.die_top_taper_opening = prm.get_double("Entry taper opening");
    s.solver.tangential_penalty_ratio
      = prm.get_double("Tangential penalty ratio");
    prm.leave_subsection();

    prm.enter_subsection("Process");
    s.process.compaction_displacement
      = prm.get_double("Compaction displacement");
    s.process.unloading_displacement = prm.get_double("Unloading displacement");
    s.process.ejection_displacement  = prm.get_double("Ejection displacement");
    s.process.compaction_steps       = prm.get_integer("Compaction steps");
    s.process.unloading_steps        = prm.get_integer("Unloading steps");
    s.process.ejection_steps         = prm.get_integer("Ejection steps");
    s.process.punch_speed            = prm.get_double("Punch speed");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    s.solver.tolerance      = prm.get_double("Tolerance");
    s.solver.max_iterations = prm.get_integer("Max iterations");
    s.solver.max_step_cuts  = prm.get_integer("Max step cuts");
    s.solver.verbose        = prm.get_bool("Print Newton residuals");
    s.solver.linear_solver  = prm.get("Linear solver");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    s.output.field_interval      = prm.get_integer("Field interval");
    s.output.write_fields        = prm.get_bool("Write fields");
    s.output.write_hdf5          = prm.get_bool("Write HDF5");
    s.output.checkpoint_interval = prm.get_integer("Checkpoint interval");
    s.output.resume_from         = prm.get("Resume from");
    prm.leave_subsection();

    if (s.process.ejection_steps > 0 && s.process.unloading_steps == 0)
      input::reject_entry("Ejection steps",
                          std::to_string(s.process.ejection_steps),
                          "ejection needs an unloading stage first (Unloading "
                          "steps > 0)");
    if (!(s.process.compaction_displacement < s.solver.geometry.fill_height))
      input::reject_entry("Compaction displacement",
                          std::to_string(s.process.compaction_displacement),
                          "must be smaller than the fill height "
                            + std::to_string(s.solver.geometry.fill_height)
                            + " m");
    // A resumed run continues the same cycle: every entry but where it
    // resumes from, how often it checkpoints, how hard the solver tries
    // (a run that stopped without convergence is resumed with more
    // iterations or cuts) and how much it prints; files by their content.
    s.output.parameters
      = input::canonical_parameters(prm,
                                    {},
                                    {"Output/Resume from",
                                     "Output/Checkpoint interval",
                                     "Solver/Max iterations",
                                     "Solver/Max step cuts",
                                     "Solver/Linear solver",
                                     "Solver/Print Newton residuals"},
                                    {"Geometry/Mesh file",
                                     "Material/DPC table"});
    // A checkpoint that cannot be resumed is refused before any output
    // exists (the ranks are checked when it runs).
    if (!s.output.resume_from.empty())
      try
        {
          read_tablet_resume(s.output.resume_from,
                             s.output.parameters,
                             std::nullopt);
        }
      catch (const TabletResumeError &e)
        {
          reject_resume(s, e);
        }
    return s;
  }
} // namespace compax::coupling

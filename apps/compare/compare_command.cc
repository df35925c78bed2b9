#include "apps/compare/compare_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/gnuplot.h"
#include "apps/common/material_parameters.h"
#include "apps/compare/compare_table.h"
#include "apps/compare/interior_comparison.h"
#include "apps/die/die_command.h"
#include "apps/rve/rve_parameters.h"
#include "apps/tablet/tablet_command.h"

#include "dem/solver/consolidation.h"

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    namespace fs = std::filesystem;

    constexpr double pi  = 3.14159265358979323846;
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    /// Samples of two studies this close in relative density are taken as
    /// at the same density (the RVE branches within a solver step of the
    /// requested density, the tablet ends within round-off of its target).
    constexpr double density_reach = 1e-3;
    /// Die stresses below this are not resolved [Pa] (the particle die's
    /// default resolution).
    const double pressure_resolution
      = dem::ConsolidationOptions{}.pressure_resolution();

    /// Entries of a sub-study's ParameterHandler ("Packing/Die diameter")
    /// and their values.
    using Settings = std::vector<std::pair<std::string, std::string>>;

    /// A number as a .prm value, with enough digits that derived lengths
    /// and densities are passed on exactly enough.
    std::string
    number(const double value)
    {
      std::ostringstream s;
      s << std::setprecision(15) << value;
      return s.str();
    }

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

    /// Sets "A/B/name" = value in prm; a value the entry's pattern rejects
    /// is an InputError naming @p study.
    void
    set_entry(dealii::ParameterHandler &prm,
              const std::string        &path,
              const std::string        &value,
              const std::string        &study)
    {
      std::vector<std::string> parts;
      {
        std::stringstream s(path);
        for (std::string p; std::getline(s, p, '/');)
          parts.push_back(p);
      }
      for (std::size_t k = 0; k + 1 < parts.size(); ++k)
        prm.enter_subsection(parts[k]);
      try
        {
          prm.set(parts.back(), value);
        }
      catch (const dealii::ExceptionBase &)
        {
          for (std::size_t k = 0; k + 1 < parts.size(); ++k)
            prm.leave_subsection();
          throw InputError("the " + study + " study does not accept '" + path
                           + "' = " + value);
        }
      for (std::size_t k = 0; k + 1 < parts.size(); ++k)
        prm.leave_subsection();
    }

    /// The parameters of @p command with @p settings applied and checked
    /// (InputError from the command, prefixed with the study's name).
    /// The compare entry a sub-study entry was set from, for messages:
    /// "Packing/Die diameter" of compax die is "Die/Die diameter" here.
    std::string
    compare_entry(const std::string &entry)
    {
      static const std::vector<std::pair<std::string, std::string>> prefixes
        = {{"Packing/", "Die/"},
           {"Protocol/", "Die/"},
           {"Multiscale/Material/", "Material/"},
           {"Multiscale/Bonding/", "Bonding/"}};
      if (entry.rfind("Material/", 0) == 0 || entry.rfind("Bonding/", 0) == 0)
        return entry;
      for (const auto &[from, to] : prefixes)
        if (entry.rfind(from, 0) == 0)
          return to + entry.substr(from.size());
      return "";
    }

    void
    prepare(const Command            &command,
            dealii::ParameterHandler &prm,
            const Settings           &settings,
            const std::string        &study)
    {
      command.declare_parameters(prm);
      for (const auto &[path, value] : settings)
        set_entry(prm, path, value, study);
      try
        {
          command.check_parameters(prm);
        }
      catch (const InputError &e)
        {
          // A rejected entry that compare set from one of its own is named
          // as the user wrote it.
          const std::string message = e.what();
          for (const auto &[path, value] : settings)
            {
              const std::string quoted = "entry '" + path + "'";
              const std::string own    = compare_entry(path);
              if (!own.empty() && message.rfind(quoted, 0) == 0)
                throw InputError("entry '" + own + "'"
                                 + message.substr(quoted.size()) + " (in the "
                                 + study + " study)");
            }
          throw InputError("in the " + study
                           + " study compare sets up: " + message);
        }
    }

    /// The state of one sub-study for compare.md.
    struct StudyStatus
    {
      std::string name, folder;
      bool        ran  = false;
      int         code = success;
      std::string message;
      double      seconds = 0.0;
    };

    /// Runs @p command in-process in the folder @p status.folder of
    /// @p parent (created here, with the parameters it ran with in
    /// parameters.prm) and records in @p status that it ran, its exit code,
    /// time and message: an exception of the study is reported in the
    /// message and gives not_converged (bad input stays bad input).
    void
    run_study(const Command     &command,
              const Settings    &settings,
              const fs::path    &parent,
              const std::string &study,
              StudyStatus       &status)
    {
      status.ran                       = true;
      const fs::path           folder  = parent / status.folder;
      std::string             &message = status.message;
      double                  &seconds = status.seconds;
      dealii::ParameterHandler prm;
      prepare(command, prm, settings, study);
      fs::create_directories(folder);
      {
        std::ofstream out(folder / "parameters.prm");
        prm.print_parameters(
          out,
          dealii::ParameterHandler::ShortPRM
            | dealii::ParameterHandler::KeepDeclarationOrder);
      }
      std::cout << "\n=== compax compare: " << study << " study in "
                << folder.filename().string() << "/ ===" << std::endl;
      const auto start = std::chrono::steady_clock::now();
      int        code  = success;
      try
        {
          code = command.run(prm, folder);
          if (code != success)
            message = "compax " + command.name() + " stopped with exit code "
                      + std::to_string(code)
                      + (code == not_converged ? " (did not converge)" : "");
        }
      catch (const InputError &e)
        {
          throw InputError("in the " + study
                           + " study compare sets up: " + e.what());
        }
      catch (const std::exception &e)
        {
          message = e.what();
          code    = not_converged;
        }
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now()
                                              - start)
                  .count();
      if (!message.empty())
        std::cout << "compax compare: the " << study
                  << " study failed: " << message << std::endl;
      status.code = code;
    }

    /// What compare reads from its parameters.
    struct CompareSetup
    {
      Settings            material; // Material/... entries
      Settings            bonding;  // Bonding/... entries
      double              die_diameter  = 0.0;
      double              final_density = 0.0;
      std::vector<double> unloading_points;
      std::string         unloading_list;
      double              friction = 0.0;
      Settings            die; // everything for compax die
      int                 rve_particles = 0, rve_seed = 0, rve_shear_steps = 0;
      double              rve_strain_step = 0.0;
      std::vector<double> loose_branches;
      double              rve_final_density = 0.0;
      int  tablet_cells = 0, tablet_steps = 0, tablet_unloading_steps = 0;
      bool fe2           = true;
      int  fe2_particles = 0, fe2_pool = 0, fe2_cells = 0, fe2_steps = 0,
          fe2_cuts     = 0;
      double fe2_floor = 0.0;
    };

    void
    declare(dealii::ParameterHandler &prm)
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
      declare_particle_material(prm, material_1);
      prm.leave_subsection();

      declare_rve_bonding_parameters(prm);

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

    CompareSetup
    read(dealii::ParameterHandler &prm)
    {
      CompareSetup c;
      c.material = copy_section(prm, "Material", material_entries);
      c.bonding  = copy_section(prm, "Bonding", bonding_entries);

      prm.enter_subsection("Die");
      c.die_diameter     = prm.get_double("Die diameter");
      c.final_density    = prm.get_double("Final relative density");
      c.unloading_points = get_real_list(prm, "Unloading points");
      c.unloading_list   = prm.get("Unloading points");
      c.friction         = prm.get_double("Die-wall friction coefficient");
      c.die              = {{"Packing/Die diameter", prm.get("Die diameter")},
                            {"Packing/Number of particles", prm.get("Number of particles")},
                            {"Packing/Seed", prm.get("Seed")},
                            {"Protocol/Final relative density",
                             prm.get("Final relative density")},
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

      const auto &u = c.unloading_points;
      if (u.size() < 2)
        reject_entry("Die/Unloading points",
                     c.unloading_list,
                     "needs at least two densities (the RVE database "
                     "fits a density-dependent cap through its branches)");
      for (std::size_t k = 0; k < u.size(); ++k)
        if (!(u[k] > 0.0 && u[k] <= c.final_density)
            || (k > 0 && !(u[k] > u[k - 1])))
          reject_entry("Die/Unloading points",
                       c.unloading_list,
                       "increasing densities in (0, Final relative density "
                       "= "
                         + format_number(c.final_density) + "] are needed");
      if (std::abs(u.back() - c.final_density) > 1e-12)
        reject_entry("Die/Unloading points",
                     c.unloading_list,
                     "the last one must be the Final relative density "
                       + format_number(c.final_density)
                       + ": the ejection pressures are compared there");

      prm.enter_subsection("RVE");
      c.rve_particles   = prm.get_integer("Number of particles");
      c.rve_seed        = prm.get_integer("Seed");
      c.rve_strain_step = prm.get_double("Compaction strain step");
      c.rve_shear_steps = prm.get_integer("Shear steps");
      c.loose_branches  = get_real_list(prm, "Loose branches");
      c.rve_final_density
        = rve_final_density(prm.get("Final relative density"), c.final_density);
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

    /// The particle bed as deposited: what the tablet is filled with.
    struct Fill
    {
      double relative_density, height;
    };

    /// Settings of `compax tablet` for the same die and material as the
    /// particle study, in database or FE2 mode.
    Settings
    tablet_settings(const CompareSetup        &c,
                    const Fill                &fill,
                    const std::vector<double> &branches,
                    const bool                 fe2)
    {
      const double H_final
        = fill.height * fill.relative_density / c.final_density;
      std::ostringstream list;
      for (std::size_t k = 0; k < branches.size(); ++k)
        list << (k ? ", " : "") << number(branches[k]);
      Settings s = {
        {"Geometry/Die diameter", number(c.die_diameter)},
        {"Geometry/Fill height", number(fill.height)},
        {"Mesh/Radial cells",
         std::to_string(fe2 ? c.fe2_cells : c.tablet_cells)},
        {"Material/Model", fe2 ? "multiscale-fe2" : "multiscale-database"},
        {"Material/Initial relative density", number(fill.relative_density)},
        // The particle die's walls are frictionless during compaction and
        // unloading; mu enters only the ejection pressure (Sec. 5.4).
        {"Die/Wall friction coefficient", "0"},
        {"Process/Compaction displacement", number(fill.height - H_final)},
        {"Process/Compaction steps",
         std::to_string(fe2 ? c.fe2_steps : c.tablet_steps)},
        {"Process/Unloading displacement", number(fe2 ? 0.0 : 0.4 * H_final)},
        {"Process/Unloading steps",
         std::to_string(fe2 ? 0 : c.tablet_unloading_steps)},
        {"Process/Ejection steps", "0"},
        {"Output/Write fields", "false"},
        {"Output/Write HDF5", "false"},
        {"Output/Checkpoint interval", "0"},
        {"Multiscale/Packing/Number of particles",
         std::to_string(fe2 ? c.fe2_particles : c.rve_particles)},
        {"Multiscale/Packing/Seed", std::to_string(c.rve_seed)},
        {"Multiscale/Packing/Initial relative density",
         number(fill.relative_density)},
        {"Multiscale/Paths/Final relative density",
         number(c.rve_final_density)},
        {"Multiscale/Paths/Branch densities", list.str()},
        {"Multiscale/Paths/Compaction strain step", number(c.rve_strain_step)},
        {"Multiscale/Paths/Shear steps", std::to_string(c.rve_shear_steps)}};
      if (fe2)
        {
          s.emplace_back("Multiscale/Pool size", std::to_string(c.fe2_pool));
          s.emplace_back("Multiscale/Tangent floor modulus",
                         number(c.fe2_floor));
          s.emplace_back("Solver/Max step cuts", std::to_string(c.fe2_cuts));
        }
      for (const auto &[entry, value] : c.material)
        s.emplace_back("Multiscale/" + entry, value);
      for (const auto &[entry, value] : c.bonding)
        s.emplace_back("Multiscale/" + entry, value);
      return s;
    }

    /// Punch pressure against relative density over the compaction rows of
    /// a tablet.csv. The density is the rigid die's, rho_0 H_0 / H with H
    /// the punch gap (the lower punch rests during compaction), as the
    /// particle die measures it: the mesh's mean density also counts the
    /// penalty wall's give, which grows with the wall pressure.
    DensitySeries
    tablet_compaction(const CsvTable &t, const Fill &fill)
    {
      DensitySeries s;
      const auto   &stage = t.text("stage");
      const auto    upper = t.numbers("upper_punch_displacement");
      const auto    lower = t.numbers("lower_punch_displacement");
      const auto    p     = t.numbers("upper_punch_pressure");
      for (std::size_t k = 0; k < t.rows(); ++k)
        if (stage[k] == "compaction")
          {
            const double gap = fill.height - upper[k] - lower[k];
            s.x.push_back(fill.relative_density * fill.height / gap);
            s.y.push_back(p[k]);
          }
      return s;
    }

    /// Summary statistics of the rows of one comparison.
    void
    summarize(std::ostream                     &out,
              const std::vector<ComparisonRow> &rows,
              const std::string                &name)
    {
      std::size_t n = 0, missing = 0;
      double      sum = 0.0, largest = 0.0;
      for (const ComparisonRow &r : rows)
        if (r.comparison == name)
          {
            const double d = r.relative_difference();
            if (std::isfinite(d))
              {
                ++n;
                sum += std::abs(d);
                largest = std::max(largest, std::abs(d));
              }
            else
              ++missing;
          }
      out << "| " << name << " | " << n << " | " << missing << " | ";
      if (n > 0)
        out << std::setprecision(3) << 100 * sum / n << " | " << 100 * largest
            << " |\n";
      else
        out << "- | - |\n";
    }

    void
    plot(const fs::path &folder, const Fill &fill, const bool with_fe2)
    {
      // The rigid die's density of tablet_compaction().
      const std::string rigid_die_density
        = "(" + number(fill.relative_density * fill.height) + "/("
          + number(fill.height)
          + "-column('upper_punch_displacement')"
            "-column('lower_punch_displacement')))";
      const std::string compaction
        = "(strcol('stage') eq 'compaction' ? column('upper_punch_pressure')"
          "/1e6 : 1/0)";
      std::ostringstream s;
      s << "set datafile columnheaders\n"
        << "set key top left\n"
        << "set multiplot layout 2,2\n"
        << "set xlabel 'relative density (in die) [-]'\n"
        << "set ylabel 'tablet Young''s modulus [GPa]'\n"
        << "plot 'die/branches.csv' using (column('rho_max_in_die')):"
           "(column('tablet_youngs_modulus')/1e9) with points pt 7 ps 1.2 "
           "title 'particle die, unloading curve (Sec. 5.7)', "
           "'tablet-database/database/dpc_table.csv' using "
           "(column('relative_density')):(column('youngs_modulus')/1e9) "
           "with linespoints pt 5 title 'RVE (homogenized)'\n"
        << "set ylabel 'tablet Poisson''s ratio [-]'\n"
        << "plot 'die/branches.csv' using (column('rho_max_in_die')):"
           "(column('tablet_poisson_ratio')) with points pt 7 ps 1.2 "
           "title 'particle die, unloading curve (Sec. 5.7)', "
           "'tablet-database/database/dpc_table.csv' using "
           "(column('relative_density')):(column('poisson_ratio')) "
           "with linespoints pt 5 title 'RVE (homogenized)'\n"
        << "set ylabel 'upper punch pressure [MPa]'\n"
        << "plot 'die/die.csv' using (column('relative_density')):"
        << compaction
        << " with points pt 7 ps 0.6 title 'particle die', "
           "'tablet-database/tablet.csv' using "
        << rigid_die_density << ":" << compaction
        << " with lines lw 2 title 'tablet, database mode'"
        << (with_fe2 ? ", 'tablet-fe2/tablet.csv' using " + rigid_die_density
                         + ":" + compaction
                         + " with linespoints pt 6 lw 2 title 'tablet, FE2'"
                     : "")
        << ", 'compare.csv' using (strcol('comparison') eq "
           "'ejection_pressure' ? column('relative_density') : 1/0):"
           "(column('reference')/1e6) with points pt 9 ps 2 title 'ejection "
           "pressure, particle die', '' using (strcol('comparison') eq "
           "'ejection_pressure' ? column('relative_density') : 1/0):"
           "(column('value')/1e6) with points pt 11 ps 2 title 'ejection "
           "pressure, tablet'\n"
        << "set ylabel 'relative difference [%]'\n"
        << "set key top right\n";
      const std::vector<std::string> names = {"youngs_modulus",
                                              "poisson_ratio",
                                              "punch_pressure",
                                              "ejection_pressure",
                                              "fe2_vs_database",
                                              "interior_sigma_zz",
                                              "interior_lateral_ratio"};
      s << "plot ";
      for (std::size_t k = 0; k < names.size(); ++k)
        s << (k ? ", " : "") << "'compare.csv' using (strcol('comparison') eq '"
          << names[k]
          << "' ? column('relative_density') : 1/0):"
             "(100*column('relative_difference')) with points pt "
          << 5 + 2 * k << " title '" << names[k] << "' noenhanced";
      s << "\nunset multiplot\n";
      render_png(folder, "compare.gp", s.str(), "compare.png");
    }

    class CompareCommand : public Command
    {
    public:
      std::string
      name() const override
      {
        return "compare";
      }

      std::string
      summary() const override
      {
        return "particle die vs RVE moduli vs multiscale tablet (database, "
               "FE2)";
      }

      std::string
      description() const override
      {
        return "Runs, for one die and one particle material, the direct "
               "particle simulation (compax die, in die/), the multiscale "
               "tablet on the RVE response database (compax tablet with "
               "Material/Model = multiscale-database, in tablet-database/, "
               "its database in tablet-database/database/) and, with "
               "Compare/FE2, the FE2 tablet (multiscale-fe2, in "
               "tablet-fe2/). The tablet is filled with the deposited "
               "particle bed: same die diameter, fill height and initial "
               "relative density, compacted to the same final density, "
               "frictionless walls as in the particle simulation; the RVEs "
               "start from that density and are made of the same Material "
               "and Bonding; the database branches at the die's unloading "
               "points.\n\nWrites compare.csv (columns comparison, "
               "relative_density, reference, value, relative_difference = "
               "(value - reference)/|reference|; the compared study is "
               "interpolated linearly in relative density at the reference's "
               "samples, missing values are empty): youngs_modulus and "
               "poisson_ratio (reference: the tablet's E and nu from the "
               "particle die's unloading curve, Gonzalez 2018 Sec. 5.7; "
               "value: the homogenized moduli of the RVE unloaded from the "
               "same in-die density rho_max), punch_pressure (upper punch "
               "pressure against in-die relative density during compaction; "
               "reference the particle die, value the database-mode tablet, "
               "whose density is the rigid die's, rho_0 H_0 / H from the "
               "punch gap, as in the particle die), "
               "ejection_pressure (mu times the residual die-wall force "
               "after unloading from the final density over the punch area, "
               "Sec. 5.4, for both), fe2_vs_database (punch pressure of the "
               "FE2 tablet against the database-mode tablet), "
               "interior_sigma_zz and interior_lateral_ratio (the die's "
               "interior, the particles farther than two diameters from "
               "every wall, against the RVE's uniaxial compaction path at "
               "the interior's own solid fraction: axial stress, and "
               "sigma_rr/sigma_zz against the RVE's lateral "
               "(sigma_xx+sigma_yy)/2 over sigma_zz); those rows also go "
               "to interior.csv (relative_density_die, "
               "relative_density_interior, sigma_zz_interior, "
               "sigma_rr_interior, sigma_zz_rve, sigma_xx_rve; stresses in "
               "Pa, tension positive; the RVE's empty outside the density "
               "range of its compaction path). Also "
               "compare.md (setup, per-study status and time, mean and "
               "largest relative differences), compare.png with "
               "compare.gp, and each study's own output and "
               "parameters.prm.\n\nBuilt-in default: Material 1 of "
               "Gonzalez 2018, 400 particles in a 4 mm die to 0.87 with "
               "unloading at 0.75, 0.79, 0.83, 0.87; 200-particle RVE "
               "database; FE2 with 60-particle RVEs on one radial cell "
               "(experimental: it may stop near the jamming transition, "
               "which compare.md then reports); about 1.5 min, most of it "
               "FE2 (Compare/FE2 = false: about 15 s).";
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        const CompareSetup c = read(prm);
        // The particle study is fully determined now; check it.
        dealii::ParameterHandler die;
        prepare(*make_die_command(), die, c.die, "die");
      }

      int
      run(dealii::ParameterHandler &prm, const fs::path &folder) const override
      {
        const CompareSetup c = read(prm);
        StudyStatus        die, database, fe2;
        die.name        = "particle die";
        die.folder      = "die";
        database.name   = "tablet, database mode";
        database.folder = "tablet-database";
        fe2.name        = "tablet, FE2 mode";
        fe2.folder      = "tablet-fe2";

        // (1) The particle die.
        const auto die_command = make_die_command();
        run_study(*die_command, c.die, folder, "particle die", die);
        if (!fs::is_regular_file(folder / "die" / "die.csv"))
          return not_converged;
        const CsvTable die_csv(folder / "die" / "die.csv");
        if (die_csv.rows() == 0)
          return not_converged;
        const Fill fill{die_csv.numbers("relative_density").front(),
                        die_csv.numbers("punch_gap").front()};
        std::cout << "compax compare: deposited bed: relative density "
                  << fill.relative_density << ", height " << fill.height * 1e3
                  << " mm" << std::endl;
        if (!(fill.relative_density < 0.74))
          throw InputError("the deposited die bed has relative density "
                           + format_number(fill.relative_density)
                           + ", too dense to start an RVE from (< 0.74)");

        // The die's branches: rho_max, E, nu, ejection pressure.
        std::vector<ComparisonRow> rows;
        DensitySeries              die_E, die_nu, die_eject;
        if (fs::is_regular_file(folder / "die" / "branches.csv"))
          {
            const CsvTable b(folder / "die" / "branches.csv");
            const auto     rho = b.numbers("rho_max_in_die");
            const auto     E   = b.numbers("tablet_youngs_modulus");
            const auto     nu  = b.numbers("tablet_poisson_ratio");
            const auto     ej  = b.numbers("ejection_pressure");
            for (std::size_t k = 0; k < b.rows(); ++k)
              {
                die_E.x.push_back(rho[k]);
                die_E.y.push_back(E[k]);
                die_nu.x.push_back(rho[k]);
                die_nu.y.push_back(nu[k]);
                die_eject.x.push_back(rho[k]);
                die_eject.y.push_back(ej[k]);
              }
          }
        // The database branches where the die was unloaded (above the
        // deposited density, where an RVE can start) and at the loose
        // branches below them.
        std::vector<double> branches;
        for (const double u : c.loose_branches)
          if (u > fill.relative_density && u < c.unloading_points.front())
            branches.push_back(u);
        std::sort(branches.begin(), branches.end());
        branches.erase(std::unique(branches.begin(), branches.end()),
                       branches.end());
        const std::size_t n_loose = branches.size();
        for (const double u : c.unloading_points)
          if (u > fill.relative_density)
            branches.push_back(u);
        if (branches.size() - n_loose < 2)
          reject_entry("Die/Unloading points",
                       c.unloading_list,
                       "at least two must exceed the deposited bed's "
                       "relative density "
                         + format_number(fill.relative_density)
                         + " (RVE database branches)");

        // (2) The tablet on the RVE database.
        const auto tablet_command = make_tablet_command();
        run_study(*tablet_command,
                  tablet_settings(c, fill, branches, false),
                  folder,
                  "database-mode tablet",
                  database);

        // (3) The FE2 tablet.
        if (c.fe2)
          {
            run_study(*tablet_command,
                      tablet_settings(c, fill, branches, true),
                      folder,
                      "FE2 tablet",
                      fe2);
          }
        else
          fe2.message = "not run (Compare/FE2 = false)";

        // (a) Moduli: RVE against the particle die's unloading curve.
        DensitySeries  rve_E, rve_nu;
        const fs::path dpc
          = folder / database.folder / "database" / "dpc_table.csv";
        if (fs::is_regular_file(dpc))
          {
            const CsvTable t(dpc);
            rve_E
              = {t.numbers("relative_density"), t.numbers("youngs_modulus")};
            rve_nu
              = {t.numbers("relative_density"), t.numbers("poisson_ratio")};
          }
        for (auto &r :
             compare_series("youngs_modulus", die_E, rve_E, density_reach))
          rows.push_back(r);
        for (auto &r :
             compare_series("poisson_ratio", die_nu, rve_nu, density_reach))
          rows.push_back(r);

        // (b) Punch pressure and ejection pressure: tablet against die.
        DensitySeries die_p;
        {
          const auto &stage  = die_csv.text("stage");
          const auto  rho    = die_csv.numbers("relative_density");
          const auto  p      = die_csv.numbers("upper_punch_pressure");
          const auto  branch = die_csv.numbers("branch");
          for (std::size_t k = 0; k < die_csv.rows(); ++k)
            if (stage[k] == "compaction" && branch[k] == 0.0
                && p[k] >= pressure_resolution)
              {
                die_p.x.push_back(rho[k]);
                die_p.y.push_back(p[k]);
              }
        }
        std::optional<CsvTable> tablet;
        if (fs::is_regular_file(folder / database.folder / "tablet.csv"))
          tablet.emplace(folder / database.folder / "tablet.csv");
        const DensitySeries tablet_p
          = tablet ? tablet_compaction(*tablet, fill) : DensitySeries{};
        for (auto &r :
             compare_series("punch_pressure", die_p, tablet_p, density_reach))
          rows.push_back(r);

        double tablet_ejection = nan;
        if (tablet && database.code == success)
          {
            // The residual wall force once the punch has come free (the
            // last unloading row), as in the particle die.
            const auto &stage = tablet->text("stage");
            const auto  F     = tablet->numbers("die_wall_normal_force");
            const auto  P     = tablet->numbers("upper_punch_force");
            for (std::size_t k = 0; k < tablet->rows(); ++k)
              if (stage[k] == "unloading")
                tablet_ejection
                  = P[k] == 0.0 ? c.friction * F[k]
                                    / (pi * c.die_diameter * c.die_diameter / 4)
                                : nan;
            if (!std::isfinite(tablet_ejection))
              database.message
                += "the upper punch still carries load at the end of "
                   "unloading: no ejection pressure";
          }
        {
          const double ref
            = interpolate(die_eject, c.final_density, density_reach);
          if (std::isfinite(ref) && ref != 0.0)
            rows.push_back(
              {"ejection_pressure", c.final_density, ref, tablet_ejection});
        }

        // (c) FE2 against database mode.
        DensitySeries fe2_p;
        if (fe2.ran && fs::is_regular_file(folder / fe2.folder / "tablet.csv"))
          fe2_p
            = tablet_compaction(CsvTable(folder / fe2.folder / "tablet.csv"),
                                fill);
        for (auto &r :
             compare_series("fe2_vs_database", tablet_p, fe2_p, density_reach))
          rows.push_back(r);

        // (d) The die's interior against the RVE at the interior's own
        // solid fraction.
        const fs::path rve_rows
          = folder / database.folder / "database" / "database.csv";
        if (fs::is_regular_file(rve_rows) && die_csv.has("rho_interior"))
          {
            const std::vector<InteriorRow> interior
              = compare_interior(die_csv, CsvTable(rve_rows));
            write_interior_csv(folder / "interior.csv", interior);
            for (auto &r :
                 interior_comparison_rows(interior, pressure_resolution))
              rows.push_back(r);
          }

        write_comparison_csv(folder / "compare.csv", rows);
        plot(folder, fill, fe2.ran && !fe2_p.x.empty());

        // compare.md: what was compared, how each study went.
        std::ofstream md(folder / "compare.md");
        md << "# compax compare\n\n"
           << "Die diameter " << c.die_diameter * 1e3
           << " mm; deposited particle bed: relative density "
           << fill.relative_density << ", height " << fill.height * 1e3
           << " mm (the tablet's fill); final relative density "
           << c.final_density << "; walls frictionless during compaction, "
           << "mu = " << c.friction << " in the ejection pressure.\n\n"
           << "| study | folder | exit code | time [s] | note |\n"
           << "| --- | --- | --- | --- | --- |\n";
        for (const StudyStatus *s : {&die, &database, &fe2})
          md << "| " << s->name << " | " << s->folder << "/ | "
             << (s->ran ? std::to_string(s->code) : std::string("-")) << " | "
             << std::setprecision(3) << (s->ran ? s->seconds : 0.0) << " | "
             << (s->message.empty() ? "ok" : s->message) << " |\n";
        md << "\n| comparison | rows | missing | mean abs. relative difference "
              "[%] | largest [%] |\n| --- | --- | --- | --- | --- |\n";
        for (const char *n : {"youngs_modulus",
                              "poisson_ratio",
                              "punch_pressure",
                              "ejection_pressure",
                              "fe2_vs_database",
                              "interior_sigma_zz",
                              "interior_lateral_ratio"})
          summarize(md, rows, n);
        if (fe2.ran && fe2.code != success)
          md << "\nThe FE2 tablet stopped (" << fe2.message
             << "): fe2_vs_database has values only up to the density it "
                "reached (last: "
             << (fe2_p.x.empty() ? nan : fe2_p.x.back())
             << "); the other rows are empty.\n";
        md.close();
        std::cout << "\n"
                  <<
          [&] {
            std::ifstream      in(folder / "compare.md");
            std::ostringstream text;
            text << in.rdbuf();
            return text.str();
          }() << std::flush;

        if (die.code != success || database.code != success)
          return not_converged;
        return success;
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_compare_command()
  {
    return std::make_unique<CompareCommand>();
  }
} // namespace compax::cli

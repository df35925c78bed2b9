#include "apps/bed/bed_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/gnuplot.h"
#include "dem/nonlocal/square_die_compaction.h"
#include "dem/nonlocal/two_material_bed.h"
#include "dem/wall_clock.h"
#include "io/csv_writer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>

namespace compax::cli
{
  namespace
  {
    /// Everything the study needs, read from the parameters.
    struct BedStudy
    {
      dem::TwoMaterialBed       bed;
      std::vector<std::string>  formulations;
      dem::BedCompactionOptions compaction;
      std::size_t               benchmark_particles;
      int                       benchmark_repetitions;
    };

    void
    declare_material(dealii::ParameterHandler &prm,
                     const std::string        &name,
                     const std::string        &E,
                     const std::string        &nu,
                     const std::string        &median,
                     const std::string        &sigma,
                     const std::string        &r_min,
                     const std::string        &r_max,
                     const std::string        &what)
    {
      prm.enter_subsection(name);
      declare_quantity(prm,
                       "Young's modulus",
                       E,
                       positive(),
                       "Pa",
                       "Young's modulus of " + what + ".");
      declare_quantity(prm,
                       "Poisson's ratio",
                       nu,
                       open(-1.0, 0.5),
                       "-",
                       "Poisson's ratio of " + what + ".");
      declare_quantity(prm,
                       "Median radius",
                       median,
                       positive(),
                       "m",
                       "Median R_50 of the log-normal radii (ln R normal). "
                       "Default: the geometric mean of the cut-offs.");
      declare_quantity(prm,
                       "Log standard deviation",
                       sigma,
                       non_negative(),
                       "-",
                       "Standard deviation of ln R; 0 for monodisperse. "
                       "Default: ln(R_max / R_min) / 4, so that the "
                       "cut-offs lie at -+2 sigma.");
      declare_quantity(prm,
                       "Minimum radius",
                       r_min,
                       positive(),
                       "m",
                       "Lower cut-off of the radii (rejection sampling).");
      declare_quantity(prm,
                       "Maximum radius",
                       r_max,
                       positive(),
                       "m",
                       "Upper cut-off of the radii.");
      prm.leave_subsection();
    }

    void
    read_material(dealii::ParameterHandler &prm,
                  const std::string        &name,
                  dem::ElasticMaterial     &elastic,
                  dem::SizeDistribution    &sizes)
    {
      prm.enter_subsection(name);
      elastic.youngs_modulus = prm.get_double("Young's modulus");
      elastic.poisson_ratio  = prm.get_double("Poisson's ratio");
      sizes.median_radius    = prm.get_double("Median radius");
      sizes.log_sigma        = prm.get_double("Log standard deviation");
      sizes.min_radius       = prm.get_double("Minimum radius");
      sizes.max_radius       = prm.get_double("Maximum radius");
      prm.leave_subsection();
      if (sizes.log_sigma > 0.0 && !(sizes.min_radius < sizes.max_radius))
        reject_entry(name + "/Minimum radius",
                     format_number(sizes.min_radius),
                     "must be smaller than the maximum radius "
                       + format_number(sizes.max_radius));
    }

    BedStudy
    read_study(dealii::ParameterHandler &prm)
    {
      BedStudy             s;
      dem::TwoMaterialBed &bed = s.bed;
      bed.width                = prm.get_double("Die width");
      bed.n_particles          = prm.get_integer("Number of particles");
      bed.volume_fraction_2    = prm.get_double("Material 2 volume fraction");
      for (int m = 0; m < 2; ++m)
        read_material(prm,
                      "Material " + std::to_string(m + 1),
                      bed.elastic[m],
                      bed.sizes[m]);
      bed.seed            = prm.get_integer("Seed");
      bed.initial_density = prm.get_double("Initial relative density");
      for (const auto &item :
           dealii::Utilities::split_string_list(prm.get("Formulations"), ','))
        if (!item.empty())
          {
            if (item != "hertz" && item != "nonlocal")
              reject_entry("Formulations", item, "allowed: hertz, nonlocal");
            s.formulations.push_back(item);
          }
      if (s.formulations.empty())
        reject_entry("Formulations", "''", "give hertz, nonlocal or both");
      auto &c                  = s.compaction;
      c.final_density          = prm.get_double("Final relative density");
      c.density_step           = prm.get_double("Density step");
      c.jamming_pressure       = prm.get_double("Jamming pressure");
      const std::string solver = prm.get("Solver");
      c.solver = solver == "newton-krylov" ? dem::BedSolver::newton_krylov
                 : solver == "trust-region"
                   ? dem::BedSolver::trust_region
                   : dem::BedSolver::nonlocal_trust_region;
      c.newton.force_tolerance          = prm.get_double("Force tolerance");
      c.krylov.force_tolerance          = c.newton.force_tolerance;
      c.nonlocal_newton.force_tolerance = c.newton.force_tolerance;
      c.hertz_consolidation             = prm.get_bool("Hertz consolidation");
      if (prm.get_bool("Solver trace"))
        c.krylov.trace = c.nonlocal_newton.trace = &std::cout;
      if (!(c.final_density > bed.initial_density))
        reject_entry("Final relative density",
                     format_number(c.final_density),
                     "must exceed the initial relative density "
                       + format_number(bed.initial_density));
      for (int m = 0; m < 2; ++m)
        if (2.0 * bed.sizes[m].largest() >= bed.width)
          reject_entry("Die width",
                       format_number(bed.width),
                       "the largest particles do not fit into the die");
      prm.enter_subsection("Benchmark");
      s.benchmark_particles   = prm.get_integer("Particles");
      s.benchmark_repetitions = prm.get_integer("Repetitions");
      prm.leave_subsection();
      return s;
    }

    class BedCommand : public Command
    {
    public:
      BedCommand()
          : Command(
            {"bed",
             "disordered two-material bed in a square die, Hertz against "
             "nonlocal contact (Gonzalez & Cuitino 2012, Sec. 4.2)",
             "Deposits a bed of elastic frictionless spheres of two "
             "materials (log-normal radii with cut-offs) ballistically "
             "into a die of square cross-section, then consolidates and "
             "compacts it by the upper punch under displacement control, "
             "once with Hertz contacts and once with the nonlocal contact "
             "formulation (Eqs. 5, 9, 10, Algorithm 1 at every residual "
             "evaluation). Below the jamming pressure the bed is relaxed "
             "by FIRE (rearrangement; with Hertz contacts also for the "
             "nonlocal run unless Hertz consolidation = false); above it "
             "every step is a static equilibrium solved by Newton: by "
             "default a trust region on the frozen-angle Hessian of the "
             "nonlocal formulation, finished by Newton-Krylov with the "
             "exact Jacobian (Solver).\n\nWrites bed.csv (per "
             "formulation and step: relative density, punch gap, forces "
             "on the six walls, mean lateral reaction, solver "
             "iterations, Algorithm 1 sweeps, coordination, largest "
             "gamma_NL / gamma), discrepancy.csv (load and lateral "
             "reaction of both formulations at the same densities and "
             "their relative difference), particles.csv (the deposited "
             "bed), bed_load.png (like Fig. 19, left).\n\nWith Benchmark/"
             "Particles > 0 it instead deposits that many particles in a "
             "wider die, compresses them affinely, and times one Hertz "
             "and one nonlocal residual (benchmark.csv).\n\nBuilt-in "
             "default: Sec. 4.2, 125 particles, E1 = 19 GPa, nu1 = 0.30, "
             "radii 75-80 um; E2 = 7 GPa, nu2 = 0.20, radii 125-167 um; "
             "equal solid volumes of both; 1 mm x 1 mm die; from "
             "relative density 0.42 to 0.80."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_quantity(prm,
                         "Die width",
                         "1e-3",
                         positive(),
                         "m",
                         "Side L of the square die cross-section.");
        prm.declare_entry("Number of particles",
                          "125",
                          dealii::Patterns::Integer(1, 10000000),
                          "Particles in the bed. Unit: -.");
        declare_quantity(prm,
                         "Material 2 volume fraction",
                         "0.5",
                         closed(0.0, 1.0),
                         "-",
                         "Solid volume fraction of material 2; the particle "
                         "counts follow from the mean volumes. Equal "
                         "volumes give a solid volume of 0.42 mm^3 for 125 "
                         "particles, i.e. rho = 0.42 at 1 mm height as in "
                         "the paper.");
        declare_material(prm,
                         "Material 1",
                         "19e9",
                         "0.30",
                         "77.46e-6",
                         "0.01613",
                         "75e-6",
                         "80e-6",
                         "material 1 (cellulose-like)");
        declare_material(prm,
                         "Material 2",
                         "7e9",
                         "0.20",
                         "144.5e-6",
                         "0.07236",
                         "125e-6",
                         "167e-6",
                         "material 2 (lactose-like)");
        prm.declare_entry("Seed",
                          "1",
                          dealii::Patterns::Integer(0),
                          "Seed of the deposition. Unit: -.");
        declare_quantity(prm,
                         "Initial relative density",
                         "0.42",
                         open(0.0, 1.0),
                         "-",
                         "The upper punch starts at the height of this "
                         "in-die relative density (solid volume / L^2 H), "
                         "or at the top of the deposit if that is higher.");
        declare_quantity(prm,
                         "Final relative density",
                         "0.80",
                         open(0.0, 1.5),
                         "-",
                         "In-die relative density at the end of the "
                         "compaction (the paper's 0.80). A step whose "
                         "equilibrium is not found ends the run with exit "
                         "code 3; the rows so far are kept.");
        declare_quantity(prm,
                         "Density step",
                         "0.005",
                         RealInterval(0.0, true, 0.1, false),
                         "-",
                         "Relative-density increment of each step.");
        declare_quantity(prm,
                         "Jamming pressure",
                         "1e5",
                         positive(),
                         "Pa",
                         "Upper-punch pressure at which consolidation "
                         "(FIRE) ends and Newton steps begin.");
        prm.declare_entry("Formulations",
                          "hertz, nonlocal",
                          dealii::Patterns::Anything(),
                          "Comma-separated: hertz, nonlocal. Unit: -.");
        prm.declare_entry("Solver",
                          "nonlocal-trust-region",
                          dealii::Patterns::Selection(
                            "nonlocal-trust-region|trust-region|newton-krylov"),
                          "Newton method of the jammed steps with the "
                          "nonlocal formulation: nonlocal-trust-region "
                          "(trust region on the frozen-angle Hessian "
                          "G^T (D^-1 - C)^-1 G, matrix-free, with exact "
                          "Newton-Krylov near equilibrium), trust-region "
                          "(local stiffness only, approximate symmetric K) "
                          "or newton-krylov (exact Jacobian, GMRES, "
                          "residual-norm backtracking; trust region as "
                          "fallback). Hertz always uses the trust region. "
                          "Unit: -.");
        prm.declare_entry("Solver trace",
                          "false",
                          dealii::Patterns::Bool(),
                          "Print one line per iteration of the nonlocal "
                          "trust region and Newton-Krylov (residual, trust "
                          "radius, CG/GMRES iterations, step). Unit: -.");
        prm.declare_entry("Hertz consolidation",
                          "true",
                          dealii::Patterns::Bool(),
                          "Nonlocal formulation: consolidate with Hertz "
                          "contacts (no Algorithm 1) until the jamming "
                          "pressure, then switch the nonlocal terms on; "
                          "false runs FIRE with the nonlocal forces. Unit: "
                          "-.");
        declare_quantity(prm,
                         "Force tolerance",
                         "1e-6",
                         RealInterval(0.0, true, 1.0, false),
                         "-",
                         "Equilibrium when every particle's net force is "
                         "below this times the mean contact force.");
        prm.enter_subsection("Benchmark");
        prm.declare_entry("Particles",
                          "0",
                          dealii::Patterns::Integer(0, 10000000),
                          "If > 0, time one residual of a bed of this many "
                          "particles (e.g. 6512) instead of the compaction. "
                          "Unit: -.");
        prm.declare_entry("Repetitions",
                          "20",
                          dealii::Patterns::Integer(1, 100000),
                          "Residual evaluations timed per formulation. "
                          "Unit: -.");
        prm.leave_subsection();
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        read_study(prm);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const BedStudy s = read_study(prm);
        if (s.benchmark_particles > 0)
          return benchmark(s, folder);
        const dem::TwoMaterialBed              &bed = s.bed;
        const std::vector<dem::ElasticMaterial> materials{bed.elastic[0],
                                                          bed.elastic[1]};
        const dem::ParticleSystem               p
          = dem::deposit_bed(bed, bed.width, bed.n_particles);
        write_particles(folder, p);
        const dem::SquareDie die = dem::starting_die(bed, p);
        const auto           n   = dem::material_counts(bed, bed.n_particles);
        std::cout << "bed: " << p.size() << " particles (" << n[0]
                  << " of material 1, " << n[1]
                  << " of material 2), solid volume " << p.solid_volume()
                  << " m^3, deposit top " << dem::bed_top(p)
                  << " m, start at H = " << die.height()
                  << " m, relative density "
                  << p.solid_volume() / die.enclosed_volume() << '\n';

        std::map<std::string, dem::BedCompactionResult> results;
        io::CsvWriter csv(folder / "bed.csv", bed_columns());
        // The time of each formulation's run (kept out of bed.csv, so that
        // two runs of one input give the same file).
        io::CsvWriter timing(folder / "timing.csv", {"formulation", "seconds"});
        int           status = success;
        for (const auto &f : s.formulations)
          {
            std::cout << f << ":\n";
            const auto t0 = std::chrono::steady_clock::now();
            results[f]    = dem::compact_square_die_bed(
              p, materials, die, f == "nonlocal", s.compaction, &std::cout);
            const double seconds = dem::seconds_since(t0);
            write_points(csv, f, results[f]);
            timing << f << seconds;
            timing.end_row();
            if (!summarize(f, results[f], seconds))
              status = not_converged;
          }
        csv.close();
        if (results.count("hertz") && results.count("nonlocal"))
          write_discrepancy(folder,
                            dem::formulation_discrepancies(
                              results.at("hertz"), results.at("nonlocal")));
        plot(folder);
        return status;
      }

    private:
      static void
      write_particles(const std::filesystem::path &folder,
                      const dem::ParticleSystem   &p)
      {
        io::CsvWriter csv(folder / "particles.csv",
                          {"x", "y", "z", "radius", "material"});
        for (std::size_t i = 0; i < p.size(); ++i)
          csv << p.positions[i][0] << p.positions[i][1] << p.positions[i][2]
              << p.radii[i] << static_cast<int>(p.materials[i] + 1),
            csv.end_row();
      }

      static std::vector<std::string>
      bed_columns()
      {
        return {"formulation",
                "relative_density",
                "height",
                "upper_punch",
                "lower_punch",
                "x_lower",
                "x_upper",
                "y_lower",
                "y_upper",
                "lateral",
                "jammed",
                "newton_iterations",
                "fire_iterations",
                "rejected_steps",
                "sweeps",
                "coordination",
                "nonlocal_ratio",
                "relative_residual"};
      }

      static void
      write_points(io::CsvWriter                  &csv,
                   const std::string              &f,
                   const dem::BedCompactionResult &r)
      {
        for (const auto &pt : r.points)
          {
            csv << f << pt.relative_density << pt.height;
            for (const double w : pt.wall_force)
              csv << w;
            csv << pt.lateral_force << static_cast<int>(pt.jammed)
                << pt.newton_iterations << pt.fire_iterations
                << pt.rejected_steps << static_cast<long long>(pt.sweeps)
                << pt.coordination << pt.nonlocal_ratio << pt.relative_residual;
            csv.end_row();
          }
      }

      /// Prints the run of formulation @p f; false if it stopped for a
      /// reason other than Algorithm 1 (a solver that gave up).
      static bool
      summarize(const std::string              &f,
                const dem::BedCompactionResult &r,
                const double                    seconds)
      {
        int newton = 0, steps = 0;
        for (const auto &pt : r.points)
          if (pt.jammed)
            {
              newton += pt.newton_iterations;
              ++steps;
            }
        std::cout << "  " << f << ": " << r.points.size() << " steps, " << steps
                  << " jammed steps, " << (steps ? double(newton) / steps : 0.0)
                  << " Newton iterations per jammed step, " << seconds
                  << " s\n";
        if (r.complete)
          return true;
        std::cout << "  " << f << " ends before relative density "
                  << r.failure_density << ": " << r.stop_reason << '\n';
        return r.stop_reason.find("Algorithm 1") != std::string::npos;
      }

      static void
      write_discrepancy(const std::filesystem::path                    &folder,
                        const std::vector<dem::FormulationDiscrepancy> &rows)
      {
        io::CsvWriter csv(folder / "discrepancy.csv",
                          {"relative_density",
                           "hertz_load",
                           "nonlocal_load",
                           "load_discrepancy",
                           "hertz_lateral",
                           "nonlocal_lateral",
                           "lateral_discrepancy"});
        const auto    optional = [&csv](const std::optional<double> &v) {
          if (v)
            csv << *v;
          else
            csv.empty();
        };
        double worst = 0.0, at = 0.0;
        for (const auto &r : rows)
          {
            csv << r.relative_density << r.hertz_load << r.nonlocal_load;
            optional(r.load_discrepancy);
            csv << r.hertz_lateral << r.nonlocal_lateral;
            optional(r.lateral_discrepancy);
            csv.end_row();
            if (r.load_discrepancy && std::abs(*r.load_discrepancy) > worst)
              {
                worst = std::abs(*r.load_discrepancy);
                at    = r.relative_density;
              }
          }
        csv.close();
        std::cout << "largest load discrepancy |P_NL - P_H| / P_H = " << worst
                  << " at relative density " << at << '\n';
      }

      static void
      plot(const std::filesystem::path &folder)
      {
        const auto pick = [](const std::string &f, const std::string &col) {
          return "2:(strcol(1) eq '" + f + "' ? $" + col + " : 1/0)";
        };
        const std::string script
          = "set datafile separator ','\n"
            "set xlabel 'relative density rho_R [-]'\n"
            "set ylabel 'force [N]'\n"
            "set key top left\n"
            "set title 'disordered bed in a square die (Sec. 4.2)'\n"
            "plot 'bed.csv' using "
            + pick("hertz", "4")
            + " with lines dt 2 lw 2 lc 'black' title 'applied load, Hertz', "
              "'' using "
            + pick("nonlocal", "4")
            + " with lines lw 2 lc 'black' title 'applied load, nonlocal', "
              "'' using "
            + pick("hertz", "10")
            + " with lines dt 2 lw 2 lc 'gray50' title 'lateral reaction, "
              "Hertz', '' using "
            + pick("nonlocal", "10")
            + " with lines lw 2 lc 'gray50' title 'lateral reaction, "
              "nonlocal'\n";
        render_png(folder, "bed_load.gp", script, "bed_load.png");
      }

      /// Cost of one residual, Hertz against nonlocal, on a large bed.
      static int
      benchmark(const BedStudy &s, const std::filesystem::path &folder)
      {
        io::CsvWriter csv(folder / "benchmark.csv",
                          {"formulation",
                           "particles",
                           "candidates",
                           "loaded",
                           "incidences",
                           "sweeps_cold",
                           "sweeps_warm",
                           "seconds_per_residual"});
        double        hertz_time = 0.0;
        for (const dem::ResidualTiming &t : dem::time_bed_residuals(
               s.bed, s.benchmark_particles, s.benchmark_repetitions))
          {
            if (!t.nonlocal)
              hertz_time = t.seconds_per_residual;
            csv << std::string(t.nonlocal ? "nonlocal" : "hertz")
                << static_cast<long long>(t.particles)
                << static_cast<long long>(t.candidates)
                << static_cast<long long>(t.loaded)
                << static_cast<long long>(t.incidences)
                << static_cast<long long>(t.cold_sweeps) << t.warm_sweeps
                << t.seconds_per_residual;
            csv.end_row();
            std::cout << (t.nonlocal ? "nonlocal" : "hertz   ") << ": "
                      << t.particles << " particles, " << t.candidates
                      << " candidate contacts, " << t.loaded << " loaded, "
                      << t.incidences << " incidences; Algorithm 1 sweeps cold "
                      << t.cold_sweeps << ", warm " << t.warm_sweeps << "; "
                      << t.seconds_per_residual * 1e3 << " ms per residual";
            if (t.nonlocal && hertz_time > 0.0)
              std::cout << " (" << t.seconds_per_residual / hertz_time
                        << " x Hertz)";
            std::cout << '\n';
          }
        return success;
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_bed_command()
  {
    return std::make_unique<BedCommand>();
  }
} // namespace compax::cli

#include "apps/bed/bed_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/gnuplot.h"
#include "dem/nonlocal/square_die_compaction.h"
#include "dem/nonlocal/square_die_deposition.h"
#include "dem/wall_clock.h"
#include "io/csv_writer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>

namespace compax::cli
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    struct MaterialInput
    {
      dem::ElasticMaterial  elastic;
      dem::SizeDistribution sizes;
    };

    /// Everything the study needs, read from the parameters.
    struct BedStudy
    {
      double                    width;
      std::size_t               n_particles;
      double                    volume_fraction_2;
      MaterialInput             material[2];
      std::uint64_t             seed;
      double                    initial_density;
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

    MaterialInput
    read_material(dealii::ParameterHandler &prm, const std::string &name)
    {
      MaterialInput m;
      prm.enter_subsection(name);
      m.elastic.youngs_modulus = prm.get_double("Young's modulus");
      m.elastic.poisson_ratio  = prm.get_double("Poisson's ratio");
      m.sizes.median_radius    = prm.get_double("Median radius");
      m.sizes.log_sigma        = prm.get_double("Log standard deviation");
      m.sizes.min_radius       = prm.get_double("Minimum radius");
      m.sizes.max_radius       = prm.get_double("Maximum radius");
      prm.leave_subsection();
      if (m.sizes.log_sigma > 0.0 && !(m.sizes.min_radius < m.sizes.max_radius))
        reject_entry(name + "/Minimum radius",
                     format_number(m.sizes.min_radius),
                     "must be smaller than the maximum radius "
                       + format_number(m.sizes.max_radius));
      return m;
    }

    BedStudy
    read_study(dealii::ParameterHandler &prm)
    {
      BedStudy s;
      s.width             = prm.get_double("Die width");
      s.n_particles       = prm.get_integer("Number of particles");
      s.volume_fraction_2 = prm.get_double("Material 2 volume fraction");
      s.material[0]       = read_material(prm, "Material 1");
      s.material[1]       = read_material(prm, "Material 2");
      s.seed              = prm.get_integer("Seed");
      s.initial_density   = prm.get_double("Initial relative density");
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
      if (!(c.final_density > s.initial_density))
        reject_entry("Final relative density",
                     format_number(c.final_density),
                     "must exceed the initial relative density "
                       + format_number(s.initial_density));
      for (int m = 0; m < 2; ++m)
        if (2.0 * s.material[m].sizes.largest() >= s.width)
          reject_entry("Die width",
                       format_number(s.width),
                       "the largest particles do not fit into the die");
      prm.enter_subsection("Benchmark");
      s.benchmark_particles   = prm.get_integer("Particles");
      s.benchmark_repetitions = prm.get_integer("Repetitions");
      prm.leave_subsection();
      return s;
    }

    /// Mean volume of a log-normal sphere, 4/3 pi R_50^3 exp(9 sigma^2 / 2)
    /// (the cut-offs ignored) [m^3].
    double
    mean_volume(const dem::SizeDistribution &d)
    {
      return 4.0 / 3.0 * pi * std::pow(d.median_radius, 3)
             * std::exp(4.5 * d.log_sigma * d.log_sigma);
    }

    /// Particles of each material for the requested solid volume fraction.
    std::vector<std::size_t>
    counts(const BedStudy &s, const std::size_t n)
    {
      const double f  = s.volume_fraction_2;
      const double v1 = mean_volume(s.material[0].sizes);
      const double v2 = mean_volume(s.material[1].sizes);
      const auto   n2 = static_cast<std::size_t>(
        std::lround(n * f * v1 / ((1.0 - f) * v2 + f * v1)));
      return {n - std::min(n, n2), std::min(n, n2)};
    }

    dem::ParticleSystem
    deposit(const BedStudy &s, const double width, const std::size_t n)
    {
      dem::SquareDepositionParameters d;
      d.width  = width;
      d.sizes  = {s.material[0].sizes, s.material[1].sizes};
      d.counts = counts(s, n);
      d.seed   = s.seed;
      return dem::square_die_deposition(d);
    }

    double
    top_of(const dem::ParticleSystem &p)
    {
      double top = 0.0;
      for (std::size_t i = 0; i < p.size(); ++i)
        top = std::max(top, p.positions[i][2] + p.radii[i]);
      return top;
    }

    class BedCommand : public Command
    {
    public:
      std::string
      name() const override
      {
        return "bed";
      }

      std::string
      summary() const override
      {
        return "disordered two-material bed in a square die, Hertz against "
               "nonlocal contact (Gonzalez & Cuitino 2012, Sec. 4.2)";
      }

      std::string
      description() const override
      {
        return "Deposits a bed of elastic frictionless spheres of two "
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
               "relative density 0.42 to 0.80.";
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
        const std::vector<dem::ElasticMaterial> materials{
          s.material[0].elastic, s.material[1].elastic};
        const dem::ParticleSystem p = deposit(s, s.width, s.n_particles);
        {
          io::CsvWriter csv(folder / "particles.csv",
                            {"x", "y", "z", "radius", "material"});
          for (std::size_t i = 0; i < p.size(); ++i)
            csv << p.positions[i][0] << p.positions[i][1] << p.positions[i][2]
                << p.radii[i] << static_cast<int>(p.materials[i] + 1),
              csv.end_row();
        }
        dem::SquareDie die;
        die.width = s.width;
        const double H0
          = p.solid_volume() / (s.initial_density * s.width * s.width);
        die.upper_punch_height = std::max(H0, top_of(p));
        const auto n           = counts(s, s.n_particles);
        std::cout << "bed: " << p.size() << " particles (" << n[0]
                  << " of material 1, " << n[1]
                  << " of material 2), solid volume " << p.solid_volume()
                  << " m^3, deposit top " << top_of(p)
                  << " m, start at H = " << die.height()
                  << " m, relative density "
                  << p.solid_volume() / die.enclosed_volume() << '\n';

        std::map<std::string, dem::BedCompactionResult> results;
        io::CsvWriter                                   csv(folder / "bed.csv",
                          {"formulation",
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
                                                             "relative_residual"});
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
            const auto  &r       = results[f];
            for (const auto &pt : r.points)
              {
                csv << f << pt.relative_density << pt.height;
                for (const double w : pt.wall_force)
                  csv << w;
                csv << pt.lateral_force << static_cast<int>(pt.jammed)
                    << pt.newton_iterations << pt.fire_iterations
                    << pt.rejected_steps << static_cast<long long>(pt.sweeps)
                    << pt.coordination << pt.nonlocal_ratio
                    << pt.relative_residual;
                csv.end_row();
              }
            timing << f << seconds;
            timing.end_row();
            int newton = 0, steps = 0;
            for (const auto &pt : r.points)
              if (pt.jammed)
                {
                  newton += pt.newton_iterations;
                  ++steps;
                }
            std::cout << "  " << f << ": " << r.points.size() << " steps, "
                      << steps << " jammed steps, "
                      << (steps ? double(newton) / steps : 0.0)
                      << " Newton iterations per jammed step, " << seconds
                      << " s\n";
            if (!r.complete)
              {
                std::cout << "  " << f << " ends before relative density "
                          << r.failure_density << ": " << r.stop_reason << '\n';
                if (r.stop_reason.find("Algorithm 1") == std::string::npos)
                  status = not_converged;
              }
          }
        csv.close();
        write_discrepancy(folder, results);
        plot(folder, s);
        return status;
      }

    private:
      static void
      write_discrepancy(
        const std::filesystem::path                           &folder,
        const std::map<std::string, dem::BedCompactionResult> &results)
      {
        if (!results.count("hertz") || !results.count("nonlocal"))
          return;
        const auto   &h = results.at("hertz").points;
        const auto   &n = results.at("nonlocal").points;
        io::CsvWriter csv(folder / "discrepancy.csv",
                          {"relative_density",
                           "hertz_load",
                           "nonlocal_load",
                           "load_discrepancy",
                           "hertz_lateral",
                           "nonlocal_lateral",
                           "lateral_discrepancy"});
        double        worst = 0.0, at = 0.0;
        for (const auto &a : h)
          for (const auto &b : n)
            if (std::abs(a.relative_density - b.relative_density)
                <= 1e-9 * a.relative_density)
              {
                const double la = a.wall_force[dem::SquareDie::upper_punch];
                const double lb = b.wall_force[dem::SquareDie::upper_punch];
                csv << a.relative_density << la << lb;
                if (a.jammed && b.jammed && la > 0.0)
                  csv << (lb - la) / la;
                else
                  csv.empty();
                csv << a.lateral_force << b.lateral_force;
                if (a.jammed && b.jammed && a.lateral_force > 0.0)
                  csv << (b.lateral_force - a.lateral_force) / a.lateral_force;
                else
                  csv.empty();
                csv.end_row();
                if (a.jammed && b.jammed && la > 0.0
                    && std::abs(lb - la) / la > worst)
                  {
                    worst = std::abs(lb - la) / la;
                    at    = a.relative_density;
                  }
              }
        csv.close();
        std::cout << "largest load discrepancy |P_NL - P_H| / P_H = " << worst
                  << " at relative density " << at << '\n';
      }

      static void
      plot(const std::filesystem::path &folder, const BedStudy &)
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
        const std::vector<dem::ElasticMaterial> materials{
          s.material[0].elastic, s.material[1].elastic};
        // A die wide enough that the bed is about as high as it is wide.
        const double volume = s.benchmark_particles
                              * (mean_volume(s.material[0].sizes)
                                 + mean_volume(s.material[1].sizes))
                              / 2.0;
        const double width
          = std::max(s.width, std::cbrt(volume / s.initial_density));
        dem::ParticleSystem p = deposit(s, width, s.benchmark_particles);
        dem::SquareDie      die;
        die.width              = width;
        die.upper_punch_height = top_of(p);
        // Affine compression by 2 % of the height loads the contacts of
        // the deposit.
        for (auto &x : p.positions)
          x[2] *= 0.98;
        die.upper_punch_height *= 0.98;

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
        for (const bool nonlocal : {false, true})
          {
            dem::NonlocalBedOptions o;
            o.nonlocal = nonlocal;
            dem::NonlocalBedSystem system(p, materials, die, o);
            Eigen::VectorXd        F;
            system.residual(F); // builds the list; cold start of Algorithm 1
            const unsigned cold = system.fixed_point().iterations;
            // Warm starts, as between Newton iterates: tiny moves.
            auto                  x       = system.coordinates();
            const Eigen::VectorXd x0      = x;
            std::size_t           sweeps0 = system.total_sweeps();
            const auto            t0      = std::chrono::steady_clock::now();
            for (int r = 0; r < s.benchmark_repetitions; ++r)
              {
                x = x0 * (1.0 + 1e-9 * (r % 2));
                system.residual(F);
              }
            const double t = dem::seconds_since(t0) / s.benchmark_repetitions;
            x              = x0;
            const double warm = double(system.total_sweeps() - sweeps0)
                                / s.benchmark_repetitions;
            if (!nonlocal)
              hertz_time = t;
            csv << std::string(nonlocal ? "nonlocal" : "hertz")
                << static_cast<long long>(p.size())
                << static_cast<long long>(system.n_candidates())
                << static_cast<long long>(system.n_loaded())
                << static_cast<long long>(system.n_incidences())
                << static_cast<long long>(cold) << warm << t;
            csv.end_row();
            std::cout << (nonlocal ? "nonlocal" : "hertz   ") << ": "
                      << p.size() << " particles, " << system.n_candidates()
                      << " candidate contacts, " << system.n_loaded()
                      << " loaded, " << system.n_incidences()
                      << " incidences; Algorithm 1 sweeps cold " << cold
                      << ", warm " << warm << "; " << t * 1e3
                      << " ms per residual";
            if (nonlocal && hertz_time > 0.0)
              std::cout << " (" << t / hertz_time << " x Hertz)";
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

#include "apps/mcdem/calibrate_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/gnuplot.h"
#include "apps/mcdem/mcdem_parameters.h"
#include "apps/mcdem/mcdem_progress.h"
#include "dem/dynamics/calibration.h"
#include "io/csv_table.h"
#include "io/csv_writer.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <tuple>

namespace compax::cli
{
  namespace
  {
    /// The entries of `Calibration` that name the curve to fit.
    struct CurveSource
    {
      /// CSV file; empty for a synthetic curve.
      std::string file;
      std::string strain_column, stress_column, stage_column;
      /// Packing seed of the synthetic curve.
      std::uint64_t synthetic_seed = 0;
    };

    CurveSource
    get_curve_source(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Calibration");
      // A braced list is evaluated left to right.
      const CurveSource source{prm.get("Measured curve"),
                               prm.get("Strain column"),
                               prm.get("Stress column"),
                               prm.get("Stage column"),
                               static_cast<std::uint64_t>(
                                 prm.get_integer("Synthetic seed"))};
      prm.leave_subsection();
      return source;
    }

    /// Reads a measured curve from a CSV file with a header line: the
    /// strain and stress columns, and the stage (1 loading, 2 unloading;
    /// all 1 if the column is not named or not there) by name.
    dem::StressStrainCurve
    read_curve(const CurveSource &source)
    {
      const std::filesystem::path file(source.file);
      const std::string           entry = "Calibration/Measured curve";
      if (std::filesystem::is_directory(file))
        reject_entry(entry, file.string(), "is a folder, not a CSV file");
      if (!std::filesystem::exists(file))
        reject_entry(entry, file.string(), "no such file");
      dem::StressStrainCurve curve;
      try
        {
          const io::CsvTable table = io::CsvTable::read(file);
          const std::size_t  e     = table.column(source.strain_column);
          const std::size_t  s     = table.column(source.stress_column);
          const bool         staged
            = !source.stage_column.empty() && table.has(source.stage_column);
          const std::size_t g = staged ? table.column(source.stage_column) : 0;
          for (std::size_t r = 0; r < table.rows(); ++r)
            {
              const double strain = table.number(r, e);
              const double stress = table.number(r, s);
              const double stage  = staged ? table.number(r, g) : 1.0;
              for (const auto &[value, column] :
                   {std::pair{strain, e}, std::pair{stress, s}})
                if (!std::isfinite(value))
                  throw io::CsvError(file.string(),
                                     table.where(r, column)
                                       + ": expected a finite number");
              if (stage != 1.0 && stage != 2.0)
                throw io::CsvError(file.string(),
                                   table.where(r, g)
                                     + ": expected stage 1 or 2");
              curve.strain.push_back(strain);
              curve.stress.push_back(stress);
              curve.stage.push_back(static_cast<int>(stage));
            }
        }
      catch (const io::CsvError &e)
        {
          reject_entry(entry, file.string(), e.reason());
        }
      if (curve.strain.size() < 3)
        reject_entry(entry, file.string(), "has fewer than 3 points");
      return curve;
    }

    double
    value_of(const dem::MulticontactAdhesiveLaw::Parameters &law,
             const std::string                              &name)
    {
      if (name == "k2/k1")
        return law.unloading_stiffness_ratio;
      if (name == "kc/k1")
        return law.adhesion_stiffness_ratio;
      return law.multicontact_prefactor;
    }

    /// The curve to fit: read from the source's file, or, without a file,
    /// simulated with the setup's own law on a packing of the source's
    /// synthetic seed (a synthetic test of the calibration).
    dem::StressStrainCurve
    measured_curve(const McdemSetup &setup, const CurveSource &source)
    {
      const auto truth = setup.material.normal_law;
      if (!source.file.empty())
        {
          const dem::StressStrainCurve measured = read_curve(source);
          const double                 e_max
            = *std::max_element(measured.strain.begin(), measured.strain.end());
          if (std::abs(e_max - setup.protocol.target_strain) > 0.02)
            std::cout << "Note: the measured curve reaches strain " << e_max
                      << ", the protocol's target strain is "
                      << setup.protocol.target_strain << "\n";
          return measured;
        }
      std::cout << "No measured curve: synthetic curve with k2/k1 = "
                << truth.unloading_stiffness_ratio
                << ", kc/k1 = " << truth.adhesion_stiffness_ratio
                << ", beta = " << truth.multicontact_prefactor
                << " on packing seed " << source.synthetic_seed << "\n";
      dem::RveSpec rve = setup.rve;
      rve.seed         = source.synthetic_seed;
      dem::UniaxialCompaction synthetic(setup.material, setup.settings, rve);
      synthetic.prepare(setup.protocol, [](const dem::CompactionProgress &p) {
        print_progress("[packing]", p);
      });
      return dem::compaction_curve(synthetic, truth, setup.protocol);
    }

    /// calibrated_law.prm: the fitted law as a Multi-contact law subsection.
    void
    write_calibrated_law(const std::filesystem::path  &folder,
                         const dem::CalibrationResult &result,
                         const double                  target_r2)
    {
      std::ofstream out(folder / "calibrated_law.prm");
      out << "# compax calibrate: R^2 = " << result.r2 << " after "
          << result.history.size() << " simulations (target " << target_r2
          << ")\n"
          << "subsection Multi-contact law\n"
          << "  set Unloading stiffness ratio = "
          << result.law.unloading_stiffness_ratio << "\n"
          << "  set Adhesion stiffness ratio  = "
          << result.law.adhesion_stiffness_ratio << "\n"
          << "  set Plasticity depth          = " << result.law.plasticity_depth
          << "\n"
          << "  set Multi-contact prefactor   = "
          << result.law.multicontact_prefactor << "\n"
          << "end\n";
    }

    /// calibration_fit.csv: the measured and the best simulated stress.
    void
    write_fit(const std::filesystem::path  &folder,
              const dem::StressStrainCurve &measured,
              const dem::CalibrationResult &result)
    {
      const auto    y = dem::simulated_at(measured, result.best_curve);
      io::CsvWriter fit(folder / "calibration_fit.csv",
                        {"strain", "stage", "measured", "simulated"});
      for (std::size_t k = 0; k < y.size(); ++k)
        {
          fit << measured.strain[k] << measured.stage[k] << measured.stress[k]
              << y[k];
          fit.end_row();
        }
      fit.close();
    }

    class CalibrateCommand : public Command
    {
    public:
      CalibrateCommand()
          : Command(
            {"calibrate",
             "fit k2/k1, kc/k1, beta of the multi-contact law to a "
             "stress-strain curve (R^2, Eq. 15)",
             "Calibrates the multi-contact law (Giannis 2021 Sec. 4.1.1): "
             "prepares one RVE packing as `compax mcdem` does, then runs "
             "compactions of copies of it with trial law parameters chosen "
             "by a Nelder-Mead search that maximizes R^2 (Eq. 15) between "
             "the measured stress and the simulated plate stress at the "
             "measured strains (loading and, if the curve has a stage "
             "column, unloading), until R^2 exceeds the target (paper: "
             "0.95) or the simulation budget is spent. The protocol's "
             "target strain should be the measured curve's largest "
             "strain.\n\nWrites calibration.csv (every simulation: the "
             "parameters and R^2), calibrated_law.prm (the Multi-contact "
             "law subsection with the best parameters and its R^2), "
             "calibration_fit.csv (strain, stage, measured, simulated), "
             "calibration.png. Exit code 3 if the target R^2 was not "
             "reached (the best parameters are still written).\n\n"
             "Built-in default: no measured file, so a synthetic curve is "
             "made by the code with the Multi-contact law entries (MCC-A, "
             "Table 3) on a packing with another seed (Synthetic seed), "
             "loaded to 57% strain; beta, k2/k1 and kc/k1 are fitted from "
             "the initial values on the packing of Cell/Seed. About a "
             "minute."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_mcdem_parameters(prm, 100.0, 100.0);
        prm.enter_subsection("Calibration");
        prm.declare_entry("Measured curve",
                          "",
                          dealii::Patterns::Anything(),
                          "CSV file with a header line; empty: a synthetic "
                          "curve made by the code (see Synthetic seed). Unit: "
                          "-.");
        prm.declare_entry("Strain column",
                          "strain",
                          dealii::Patterns::Anything(),
                          "Column of the strain (compression positive). "
                          "Unit: -.");
        prm.declare_entry("Stress column",
                          "stress_zz",
                          dealii::Patterns::Anything(),
                          "Column of the axial stress (compression positive). "
                          "Unit: Pa.");
        prm.declare_entry("Stage column",
                          "stage",
                          dealii::Patterns::Anything(),
                          "Column with 1 for loading and 2 for unloading "
                          "points; if absent, all points are loading. Unit: "
                          "-.");
        prm.declare_entry("Synthetic seed",
                          "1001",
                          dealii::Patterns::Integer(0),
                          "Packing seed of the synthetic curve (different "
                          "from Cell/Seed). Unit: -.");
        prm.declare_entry("Fitted parameters",
                          "k2/k1, kc/k1, beta",
                          dealii::Patterns::List(dealii::Patterns::Selection(
                                                   "k2/k1|kc/k1|beta"),
                                                 1,
                                                 3),
                          "Which law parameters to fit. Unit: -.");
        prm.declare_entry("Initial values",
                          "50, 0.2, 0.5",
                          dealii::Patterns::List(dealii::Patterns::Double(0.0),
                                                 1,
                                                 3),
                          "Start of the search, one per fitted parameter. "
                          "Unit: -.");
        prm.declare_entry("Lower bounds",
                          "1, 0, 0",
                          dealii::Patterns::List(dealii::Patterns::Double(0.0),
                                                 1,
                                                 3),
                          "One per fitted parameter (k2/k1 >= 1). Unit: -.");
        prm.declare_entry("Upper bounds",
                          "300, 2, 5",
                          dealii::Patterns::List(dealii::Patterns::Double(0.0),
                                                 1,
                                                 3),
                          "One per fitted parameter. Unit: -.");
        declare_quantity(prm,
                         "Target R2",
                         "0.95",
                         open(0.0, 1.0),
                         "-",
                         "Stop when R^2 (Eq. 15) exceeds this (paper: 0.95).");
        prm.declare_entry("Maximum simulations",
                          "30",
                          dealii::Patterns::Integer(1, 10000),
                          "Budget of compaction simulations. Unit: -.");
        prm.leave_subsection();
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        get_mcdem_setup(prm);
        spec(prm);
        const CurveSource source = get_curve_source(prm);
        if (!source.file.empty())
          read_curve(source);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        McdemSetup                 setup = get_mcdem_setup(prm);
        const dem::CalibrationSpec s     = spec(prm);

        auto progress = [](const dem::CompactionProgress &p) {
          print_progress("[packing]", p);
        };
        const auto                   truth    = setup.material.normal_law;
        const CurveSource            source   = get_curve_source(prm);
        const dem::StressStrainCurve measured = measured_curve(setup, source);
        dem::UniaxialCompaction      prepared(setup.material,
                                         setup.settings,
                                         setup.rve);
        prepared.prepare(setup.protocol, progress);
        std::cout << "Fitting on " << prepared.dem().particles().size()
                  << " particles (seed " << setup.rve.seed << ")\n";

        io::CsvWriter history(
          folder / "calibration.csv",
          {"simulation", "k2_over_k1", "kc_over_k1", "beta", "r2"});
        int        count  = 0;
        const auto result = dem::calibrate(
          measured,
          prepared,
          setup.material.normal_law,
          setup.protocol,
          s,
          [&](const dem::CalibrationStep &step) {
            ++count;
            history << count << step.law.unloading_stiffness_ratio
                    << step.law.adhesion_stiffness_ratio
                    << step.law.multicontact_prefactor << step.r2;
            history.end_row();
            std::cout << "simulation " << count
                      << ": k2/k1 = " << step.law.unloading_stiffness_ratio
                      << ", kc/k1 = " << step.law.adhesion_stiffness_ratio
                      << ", beta = " << step.law.multicontact_prefactor
                      << "  R^2 = " << step.r2 << std::endl;
          });
        history.close();

        write_calibrated_law(folder, result, s.target_r2);
        write_fit(folder, measured, result);
        std::cout << "Best: ";
        for (std::size_t d = 0; d < s.parameters.size(); ++d)
          std::cout << s.parameters[d] << " = "
                    << value_of(result.law, s.parameters[d])
                    << (source.file.empty()
                          ? " (synthetic: "
                              + std::to_string(value_of(truth, s.parameters[d]))
                              + ")"
                          : std::string())
                    << "  ";
        std::cout << "\nR^2 = " << result.r2
                  << (result.reached_target ? " > " : " <= ") << s.target_r2
                  << " after " << result.history.size() << " simulations\n";
        render_png(folder,
                   "calibration.gp",
                   "set datafile separator ','\n"
                   "set xlabel 'strain [-]'\nset ylabel 'axial stress {/Symbol "
                   "s}_{zz} [MPa]'\n"
                   "set key top left\n"
                   "plot 'calibration_fit.csv' every ::1 using 1:($3/1e6) "
                   "with points pt 7 title 'measured', '' every ::1 using "
                   "1:($4/1e6) with lines lw 2 title 'calibrated MC-DEM'\n",
                   "calibration.png");
        return result.reached_target ? success : not_converged;
      }

    private:
      static dem::CalibrationSpec
      spec(dealii::ParameterHandler &prm)
      {
        dem::CalibrationSpec s;
        prm.enter_subsection("Calibration");
        s.parameters.clear();
        for (const auto &item :
             dealii::Utilities::split_string_list(prm.get("Fitted parameters"),
                                                  ','))
          s.parameters.push_back(item);
        s.initial                 = get_real_list(prm, "Initial values");
        s.lower                   = get_real_list(prm, "Lower bounds");
        s.upper                   = get_real_list(prm, "Upper bounds");
        s.target_r2               = prm.get_double("Target R2");
        s.max_simulations         = prm.get_integer("Maximum simulations");
        const std::string initial = prm.get("Initial values");
        const std::string lower   = prm.get("Lower bounds");
        const std::string upper   = prm.get("Upper bounds");
        prm.leave_subsection();
        const std::size_t n = s.parameters.size();
        for (const auto &[name, text, values] :
             {std::tuple{"Initial values", &initial, &s.initial},
              std::tuple{"Lower bounds", &lower, &s.lower},
              std::tuple{"Upper bounds", &upper, &s.upper}})
          if (values->size() != n)
            reject_entry(std::string("Calibration/") + name,
                         *text,
                         "give one value per fitted parameter ("
                           + std::to_string(n) + ")");
        for (std::size_t d = 0; d < n; ++d)
          if (!(s.lower[d] < s.upper[d]))
            reject_entry("Calibration/Lower bounds",
                         lower,
                         "the lower bound of " + s.parameters[d] + " ("
                           + format_number(s.lower[d])
                           + ") must be below its upper bound ("
                           + format_number(s.upper[d]) + ")");
        for (std::size_t d = 0; d < n; ++d)
          {
            if (!(s.lower[d] <= s.initial[d] && s.initial[d] <= s.upper[d]))
              reject_entry("Calibration/Initial values",
                           initial,
                           "each initial value must lie within its bounds");
            if (s.parameters[d] == "k2/k1" && s.lower[d] < 1.0)
              reject_entry("Calibration/Lower bounds",
                           std::to_string(s.lower[d]),
                           "k2/k1 must be at least 1");
          }
        return s;
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_calibrate_command()
  {
    return std::make_unique<CalibrateCommand>();
  }
} // namespace compax::cli

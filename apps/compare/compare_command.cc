#include "apps/compare/compare_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/compare/compare_outputs.h"
#include "apps/compare/compare_parameters.h"
#include "apps/compare/compare_studies.h"
#include "apps/die/die_command.h"
#include "apps/tablet/tablet_command.h"
#include "coupling/scale_comparison.h"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    namespace fs = std::filesystem;

    /**
     * @p value as die.csv records it (10 significant digits,
     * dem::DieCompaction::write_csv_row). The tablets are filled with the
     * bed die.csv reports, so that die/die.csv and the tablets'
     * parameters.prm agree and a sub-study reruns from them alike: the FE2
     * tablet near jamming is so sensitive that a fill height 4e-11 off
     * moves its punch pressure by 7 %.
     */
    double
    as_in_die_csv(const double value)
    {
      std::ostringstream s;
      s << std::setprecision(10) << value;
      return std::strtod(s.str().c_str(), nullptr);
    }

    /// Where the tablets start: the particle die's deposited bed, and the
    /// RVE database branches above it.
    struct TabletStart
    {
      coupling::DepositedFill fill;
      std::vector<double>     branches;
    };

    /// The tablets' start after the particle die @p die; InputError if
    /// the bed is too dense for an RVE or too few unloading points lie
    /// above it.
    TabletStart
    tablet_start(const coupling::ScaleComparison &comparison,
                 const dem::DieStudyResult       &die,
                 const CompareSetup              &c)
    {
      TabletStart start;
      try
        {
          const coupling::DepositedFill fill
            = coupling::ScaleComparison::deposited_fill(die);
          start.fill = {as_in_die_csv(fill.relative_density),
                        as_in_die_csv(fill.height)};
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError(e.what());
        }
      std::cout << "compax compare: deposited bed: relative density "
                << start.fill.relative_density << ", height "
                << start.fill.height * 1e3 << " mm" << std::endl;
      try
        {
          start.branches = comparison.database_branches(start.fill);
        }
      catch (const std::invalid_argument &e)
        {
          reject_entry("Die/Unloading points", c.unloading_list, e.what());
        }
      return start;
    }

    class CompareCommand : public Command
    {
    public:
      CompareCommand()
          : Command(
            {"compare",
             "particle die vs RVE moduli vs multiscale tablet (database, "
             "FE2)",
             "Runs, for one die and one particle material, the direct "
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
             "interior, the region farther than two diameters from "
             "every wall with each sphere counted by its volume inside, "
             "against the RVE's uniaxial compaction path at "
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
             "FE2 (Compare/FE2 = false: about 15 s)."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_compare_parameters(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        const CompareSetup c = read_compare_setup(prm);
        // The particle study is fully determined now; check it.
        dealii::ParameterHandler die;
        prepare(*make_die_command(), die, c.die, "die");
      }

      int
      run(dealii::ParameterHandler &prm, const fs::path &folder) const override
      {
        const CompareSetup              c = read_compare_setup(prm);
        const coupling::ScaleComparison comparison(c.comparison);
        StudyStatus                     die{"particle die", "die"},
          database{"tablet, database mode", "tablet-database"},
          fe2{"tablet, FE2 mode", "tablet-fe2"};

        // (1) The particle die.
        std::optional<DieRun> die_run;
        run_study(*make_die_command(),
                  c.die,
                  folder,
                  "particle die",
                  die,
                  [&](dealii::ParameterHandler &p, const fs::path &f) {
                    die_run = run_die(p, f);
                    return die_run->code;
                  });
        if (!die_run || die_run->result.rows.empty())
          return not_converged;
        const TabletStart start = tablet_start(comparison, die_run->result, c);
        const coupling::DepositedFill &fill = start.fill;

        // (2) The tablet on the RVE database, (3) the FE2 tablet.
        const auto               tablet_command = make_tablet_command();
        std::optional<TabletRun> tablet, fe2_tablet;
        const auto run_tablet_into = [](std::optional<TabletRun> &into) {
          return [&into](dealii::ParameterHandler &p, const fs::path &f) {
            into = run_tablet(p, f);
            return into->code;
          };
        };
        run_study(*tablet_command,
                  tablet_settings(c, fill, start.branches, false),
                  folder,
                  "database-mode tablet",
                  database,
                  run_tablet_into(tablet));
        if (c.fe2)
          run_study(*tablet_command,
                    tablet_settings(c, fill, start.branches, true),
                    folder,
                    "FE2 tablet",
                    fe2,
                    run_tablet_into(fe2_tablet));
        else
          fe2.message = "not run (Compare/FE2 = false)";

        coupling::ScaleComparisonInputs in;
        in.die = &die_run->result;
        if (tablet && tablet->database)
          in.database = &*tablet->database;
        if (tablet && tablet->result)
          in.tablet = &*tablet->result;
        if (fe2_tablet && fe2_tablet->result)
          in.fe2 = &*fe2_tablet->result;
        const coupling::ScaleComparisonResult result
          = comparison.compare(fill, in);
        database.message += result.tablet_note;

        if (result.interior)
          write_interior_csv(folder / "interior.csv", *result.interior);
        write_comparison_csv(folder / "compare.csv", result.rows);
        plot_comparison(folder,
                        fill,
                        fe2.ran && !result.fe2_compaction.x.empty());
        write_compare_md(
          folder / "compare.md", c, fill, {&die, &database, &fe2}, result);
        std::ifstream md(folder / "compare.md");
        std::cout << "\n" << md.rdbuf() << std::flush;
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

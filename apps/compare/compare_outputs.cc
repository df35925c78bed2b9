#include "apps/compare/compare_outputs.h"

#include "apps/common/gnuplot.h"
#include "io/csv_writer.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    /// The comparisons of compare.csv, in order.
    const std::vector<std::string> comparison_names
      = {"youngs_modulus",
         "poisson_ratio",
         "punch_pressure",
         "ejection_pressure",
         "fe2_vs_database",
         "interior_sigma_zz",
         "interior_lateral_ratio"};

    /// The row of compare.md's table of one comparison.
    void
    summarize(std::ostream                               &out,
              const std::vector<coupling::ComparisonRow> &rows,
              const std::string                          &name)
    {
      const coupling::ComparisonSummary s = coupling::summarize(rows, name);
      out << "| " << name << " | " << s.compared << " | " << s.missing << " | ";
      if (s.compared > 0)
        out << std::setprecision(3) << 100 * s.sum_abs / s.compared << " | "
            << 100 * s.largest_abs << " |\n";
      else
        out << "- | - |\n";
    }
  } // namespace

  const std::vector<std::string> &
  comparison_columns()
  {
    static const std::vector<std::string> names = {"comparison",
                                                   "relative_density",
                                                   "reference",
                                                   "value",
                                                   "relative_difference"};
    return names;
  }

  void
  write_comparison_csv(const std::filesystem::path                &file,
                       const std::vector<coupling::ComparisonRow> &rows)
  {
    io::CsvWriter csv(file, comparison_columns());
    for (const coupling::ComparisonRow &r : rows)
      {
        csv << r.comparison << r.relative_density << r.reference;
        if (std::isfinite(r.value))
          csv << r.value << r.relative_difference();
        else
          csv.empty().empty();
        csv.end_row();
      }
    csv.close();
  }

  void
  write_interior_csv(const std::filesystem::path              &file,
                     const std::vector<coupling::InteriorRow> &rows)
  {
    io::CsvWriter csv(file,
                      {"relative_density_die",
                       "relative_density_interior",
                       "sigma_zz_interior",
                       "sigma_rr_interior",
                       "sigma_zz_rve",
                       "sigma_xx_rve"});
    for (const coupling::InteriorRow &r : rows)
      {
        for (const double v : {r.relative_density_die,
                               r.relative_density_interior,
                               r.sigma_zz_interior,
                               r.sigma_rr_interior,
                               r.sigma_zz_rve,
                               r.sigma_xx_rve})
          if (std::isfinite(v))
            csv << v;
          else
            csv.empty();
        csv.end_row();
      }
    csv.close();
  }

  void
  plot_comparison(const std::filesystem::path   &folder,
                  const coupling::DepositedFill &fill,
                  const bool                     with_fe2)
  {
    // The rigid die's density of coupling::tablet_compaction().
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
      << "plot 'die/die.csv' using (column('relative_density')):" << compaction
      << " with points pt 7 ps 0.6 title 'particle die', "
         "'tablet-database/tablet.csv' using "
      << rigid_die_density << ":" << compaction
      << " with lines lw 2 title 'tablet, database mode'"
      << (with_fe2
            ? ", 'tablet-fe2/tablet.csv' using " + rigid_die_density + ":"
                + compaction + " with linespoints pt 6 lw 2 title 'tablet, FE2'"
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
    const std::vector<std::string> &names = comparison_names;
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

  void
  write_compare_md(const std::filesystem::path            &file,
                   const CompareSetup                     &c,
                   const coupling::DepositedFill          &fill,
                   const std::vector<const StudyStatus *> &studies,
                   const coupling::ScaleComparisonResult  &result)
  {
    const coupling::ScaleComparisonSettings &s = c.comparison;
    std::ofstream                            md(file);
    md << "# compax compare\n\n"
       << "Die diameter " << s.die_diameter * 1e3
       << " mm; deposited particle bed: relative density "
       << fill.relative_density << ", height " << fill.height * 1e3
       << " mm (the tablet's fill); final relative density " << s.final_density
       << "; walls frictionless during compaction, "
       << "mu = " << s.wall_friction << " in the ejection pressure.\n\n"
       << "| study | folder | exit code | time [s] | note |\n"
       << "| --- | --- | --- | --- | --- |\n";
    for (const StudyStatus *study : studies)
      md << "| " << study->name << " | " << study->folder << "/ | "
         << (study->ran ? std::to_string(study->code) : std::string("-"))
         << " | " << std::setprecision(3) << (study->ran ? study->seconds : 0.0)
         << " | " << (study->message.empty() ? "ok" : study->message) << " |\n";
    md << "\n| comparison | rows | missing | mean abs. relative difference "
          "[%] | largest [%] |\n| --- | --- | --- | --- | --- |\n";
    for (const std::string &name : comparison_names)
      summarize(md, result.rows, name);
    const StudyStatus &fe2   = *studies.back();
    const auto        &fe2_x = result.fe2_compaction.x;
    if (fe2.ran && fe2.code != success)
      md << "\nThe FE2 tablet stopped (" << fe2.message
         << "): fe2_vs_database has values only up to the density it "
            "reached (last: "
         << (fe2_x.empty() ? std::numeric_limits<double>::quiet_NaN()
                           : fe2_x.back())
         << "); the other rows are empty.\n";
  }
} // namespace compax::cli

#include "coupling/scale_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace compax::coupling
{
  namespace
  {
    constexpr double pi  = 3.14159265358979323846;
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// A density in a message, as compax prints input values.
    std::string
    format_density(const double rho)
    {
      std::ostringstream s;
      s << rho;
      return s.str();
    }

    void
    append(std::vector<ComparisonRow> &rows, std::vector<ComparisonRow> more)
    {
      rows.insert(rows.end(), more.begin(), more.end());
    }

    /// The die's tablet E, nu (NaN where its unloading curve had too few
    /// points) and ejection pressure against rho_max of every branch.
    struct DieBranches
    {
      DensitySeries youngs_modulus, poisson_ratio, ejection_pressure;

      explicit DieBranches(const dem::DieStudyResult *die)
      {
        if (!die)
          return;
        for (const dem::BranchSummary &b : die->branches)
          {
            const bool determined = b.tablet.n_points >= 2;
            for (DensitySeries *s :
                 {&youngs_modulus, &poisson_ratio, &ejection_pressure})
              s->x.push_back(b.rho_max_in_die);
            youngs_modulus.y.push_back(determined ? b.tablet.youngs_modulus
                                                  : nan);
            poisson_ratio.y.push_back(determined ? b.tablet.poisson_ratio
                                                 : nan);
            ejection_pressure.y.push_back(b.ejection_pressure);
          }
      }
    };

    /// Upper punch pressure of the die's compaction path where resolved.
    DensitySeries
    die_compaction(const dem::DieStudyResult *die, const double resolution)
    {
      DensitySeries s;
      if (die)
        for (const dem::DieRecord &r : die->rows)
          if (r.stage == "compaction" && r.branch == 0
              && r.upper_punch_pressure >= resolution)
            {
              s.x.push_back(r.relative_density);
              s.y.push_back(r.upper_punch_pressure);
            }
      return s;
    }

    /// mu times the residual die-wall force over the punch area once the
    /// punch has come free (the last unloading step), as in the particle
    /// die; NaN if the punch still carries load then.
    double
    tablet_ejection_pressure(const TabletStudyResult       &tablet,
                             const ScaleComparisonSettings &s)
    {
      double pressure = nan;
      for (const fem::TabletStep &step : tablet.history)
        if (step.stage == fem::TabletStage::unloading)
          pressure = step.forces.upper_punch_force == 0.0
                       ? s.wall_friction * step.forces.die_wall_normal_force
                           / (pi * s.die_diameter * s.die_diameter / 4)
                       : nan;
      return pressure;
    }
  } // namespace

  ScaleComparison::ScaleComparison(ScaleComparisonSettings settings)
      : settings_(std::move(settings))
  {
  }

  DepositedFill
  ScaleComparison::deposited_fill(const dem::DieStudyResult &die)
  {
    if (die.rows.empty())
      throw std::invalid_argument("the die study has no deposited bed");
    const DepositedFill fill{die.rows.front().relative_density,
                             die.rows.front().punch_gap};
    if (!(fill.relative_density < densest_rve_start))
      throw std::invalid_argument("the deposited die bed has relative density "
                                  + format_density(fill.relative_density)
                                  + ", too dense to start an RVE from (< "
                                  + format_density(densest_rve_start) + ")");
    return fill;
  }

  std::vector<double>
  ScaleComparison::database_branches(const DepositedFill &fill) const
  {
    const auto         &unloading = settings_.unloading_points;
    std::vector<double> branches;
    for (const double u : settings_.loose_branches)
      if (u > fill.relative_density && u < unloading.front())
        branches.push_back(u);
    std::sort(branches.begin(), branches.end());
    branches.erase(std::unique(branches.begin(), branches.end()),
                   branches.end());
    const std::size_t n_loose = branches.size();
    for (const double u : unloading)
      if (u > fill.relative_density)
        branches.push_back(u);
    if (branches.size() - n_loose < 2)
      throw std::invalid_argument(
        "at least two must exceed the deposited bed's relative density "
        + format_density(fill.relative_density) + " (RVE database branches)");
    return branches;
  }

  ScaleComparisonResult
  ScaleComparison::compare(const DepositedFill         &fill,
                           const ScaleComparisonInputs &in) const
  {
    const ScaleComparisonSettings &s = settings_;
    ScaleComparisonResult          out;
    auto                          &rows = out.rows;

    // Moduli: RVE against the particle die's unloading curve.
    const DieBranches die(in.die);
    DensitySeries     rve_E, rve_nu;
    if (in.database)
      for (const DpcFitRow &r : in.database->fit)
        {
          rve_E.x.push_back(r.relative_density);
          rve_E.y.push_back(r.youngs_modulus);
          rve_nu.x.push_back(r.relative_density);
          rve_nu.y.push_back(r.poisson_ratio);
        }
    append(rows,
           compare_series(
             "youngs_modulus", die.youngs_modulus, rve_E, s.density_reach));
    append(rows,
           compare_series(
             "poisson_ratio", die.poisson_ratio, rve_nu, s.density_reach));

    // Punch pressure and ejection pressure: tablet against die.
    const DensitySeries tablet_p
      = in.tablet ? tablet_compaction(*in.tablet, fill) : DensitySeries{};
    append(rows,
           compare_series("punch_pressure",
                          die_compaction(in.die, s.pressure_resolution),
                          tablet_p,
                          s.density_reach));
    double tablet_ejection = nan;
    if (in.tablet && in.tablet->converged)
      {
        tablet_ejection = tablet_ejection_pressure(*in.tablet, s);
        if (!std::isfinite(tablet_ejection))
          out.tablet_note = "the upper punch still carries load at the end "
                            "of unloading: no ejection pressure";
      }
    const double reference
      = interpolate(die.ejection_pressure, s.final_density, s.density_reach);
    if (std::isfinite(reference) && reference != 0.0)
      rows.push_back(
        {"ejection_pressure", s.final_density, reference, tablet_ejection});

    // FE2 against database mode.
    if (in.fe2)
      out.fe2_compaction = tablet_compaction(*in.fe2, fill);
    append(rows,
           compare_series(
             "fe2_vs_database", tablet_p, out.fe2_compaction, s.density_reach));

    // The die's interior against the RVE at the interior's own solid
    // fraction.
    if (in.database && in.die)
      {
        out.interior = compare_interior(in.die->rows, in.database->database);
        append(rows,
               interior_comparison_rows(*out.interior, s.pressure_resolution));
      }
    return out;
  }

  DensitySeries
  tablet_compaction(const TabletStudyResult &tablet, const DepositedFill &fill)
  {
    DensitySeries s;
    for (const fem::TabletStep &step : tablet.history)
      if (step.stage == fem::TabletStage::compaction)
        {
          const double gap = fill.height - step.upper_punch_displacement
                             - step.lower_punch_displacement;
          s.x.push_back(fill.relative_density * fill.height / gap);
          s.y.push_back(step.forces.upper_punch_force / tablet.punch_area);
        }
    return s;
  }
} // namespace compax::coupling

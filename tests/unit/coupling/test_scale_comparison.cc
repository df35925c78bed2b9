// The scale comparison on results in memory: a series against itself
// differs by nothing, relative differences and the tablet's ejection
// pressure against hand-computed values, the database branches the tablet
// gets, and the rigid die's density of a tablet's compaction.
#include "coupling/scale_comparison.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace coupling = compax::coupling;
namespace dem      = compax::dem;
namespace fem      = compax::fem;

namespace
{
  constexpr double pi      = 3.14159265358979323846;
  constexpr double missing = std::numeric_limits<double>::quiet_NaN();

  /// A die of 4 mm to 0.87, unloaded at 0.75, 0.79, 0.83, 0.87, mu = 0.5.
  coupling::ScaleComparisonSettings
  settings()
  {
    coupling::ScaleComparisonSettings s;
    s.die_diameter     = 4e-3;
    s.final_density    = 0.87;
    s.unloading_points = {0.75, 0.79, 0.83, 0.87};
    s.loose_branches   = {0.7, 0.65, 0.65, 0.8, 0.55};
    s.wall_friction    = 0.5;
    return s;
  }

  dem::DieRecord
  die_row(const std::string &stage, const double rho, const double p)
  {
    dem::DieRecord r;
    r.stage                = stage;
    r.relative_density     = rho;
    r.punch_gap            = 1e-2 * 0.6 / rho;
    r.upper_punch_pressure = p;
    r.rho_interior         = missing;
    return r;
  }

  fem::TabletStep
  tablet_step(const fem::TabletStage stage,
              const double           travel,
              const double           punch_force,
              const double           wall_force)
  {
    fem::TabletStep s;
    s.stage                        = stage;
    s.upper_punch_displacement     = travel;
    s.forces.upper_punch_force     = punch_force;
    s.forces.die_wall_normal_force = wall_force;
    return s;
  }

  std::vector<coupling::ComparisonRow>
  named(const std::vector<coupling::ComparisonRow> &rows,
        const std::string                          &name)
  {
    std::vector<coupling::ComparisonRow> out;
    for (const auto &r : rows)
      if (r.comparison == name)
        out.push_back(r);
    return out;
  }
} // namespace

TEST(ScaleComparison, ASeriesAgainstItselfDiffersByNothing)
{
  const coupling::DensitySeries s{{0.6, 0.7, 0.75, 0.9},
                                  {1e5, -2.5e6, 3.125e7, 4e8}};
  const auto rows = coupling::compare_series("same", s, s, 1e-3);
  ASSERT_EQ(rows.size(), 4u);
  for (const auto &r : rows)
    {
      EXPECT_EQ(r.value, r.reference);
      EXPECT_EQ(r.relative_difference(), 0.0);
    }
  const coupling::ComparisonSummary summary = coupling::summarize(rows, "same");
  EXPECT_EQ(summary.compared, 4u);
  EXPECT_EQ(summary.missing, 0u);
  EXPECT_EQ(summary.largest_abs, 0.0);
}

TEST(ScaleComparison, SummaryOfHandComputedDifferences)
{
  // (5 - 4)/4 = 0.25, (-3 - -2)/2 = -0.5, a missing value, another
  // comparison.
  const std::vector<coupling::ComparisonRow> rows = {{"a", 0.7, 4.0, 5.0},
                                                     {"a", 0.8, -2.0, -3.0},
                                                     {"a", 0.9, 1.0, missing},
                                                     {"b", 0.8, 1.0, 100.0}};
  EXPECT_EQ(rows[0].relative_difference(), 0.25);
  EXPECT_EQ(rows[1].relative_difference(), -0.5);
  const coupling::ComparisonSummary s = coupling::summarize(rows, "a");
  EXPECT_EQ(s.compared, 2u);
  EXPECT_EQ(s.missing, 1u);
  EXPECT_EQ(s.sum_abs, 0.75);
  EXPECT_EQ(s.largest_abs, 0.5);
}

TEST(ScaleComparison, DatabaseBranchesLieAboveTheFill)
{
  const coupling::ScaleComparison comparison(settings());
  // Loose branches sorted, repeated and out-of-range ones dropped (0.55
  // below the fill, 0.8 above the first unloading point), then the
  // unloading points.
  EXPECT_EQ(comparison.database_branches({0.6, 1e-2}),
            (std::vector<double>{0.65, 0.7, 0.75, 0.79, 0.83, 0.87}));
  EXPECT_EQ(comparison.database_branches({0.8, 1e-2}),
            (std::vector<double>{0.83, 0.87}));
  // One unloading point above the fill: no density-dependent cap.
  EXPECT_THROW(comparison.database_branches({0.84, 1e-2}),
               std::invalid_argument);
}

TEST(ScaleComparison, DepositedFillIsTheDiesFirstRow)
{
  dem::DieStudyResult die;
  EXPECT_THROW(coupling::ScaleComparison::deposited_fill(die),
               std::invalid_argument);
  die.rows = {die_row("compaction", 0.6, 0.0), die_row("compaction", 0.7, 1e6)};
  const coupling::DepositedFill fill
    = coupling::ScaleComparison::deposited_fill(die);
  EXPECT_EQ(fill.relative_density, 0.6);
  EXPECT_EQ(fill.height, die.rows[0].punch_gap);
  die.rows[0].relative_density = 0.74;
  EXPECT_THROW(coupling::ScaleComparison::deposited_fill(die),
               std::invalid_argument);
}

TEST(ScaleComparison, TabletDensityIsTheRigidDiesFromThePunchGap)
{
  // Filled 10 mm high at 0.5: 2 mm of travel give 0.5 * 10 / 8.
  coupling::TabletStudyResult tablet;
  tablet.punch_area = 2.0;
  tablet.history    = {tablet_step(fem::TabletStage::compaction, 0.0, 0.0, 0.0),
                       tablet_step(fem::TabletStage::compaction, 2e-3, 6.0, 1.0),
                       tablet_step(fem::TabletStage::unloading, 1.9e-3, 0.0, 1.0)};
  const coupling::DensitySeries s
    = coupling::tablet_compaction(tablet, {0.5, 1e-2});
  ASSERT_EQ(s.x.size(), 2u);
  EXPECT_DOUBLE_EQ(s.x[0], 0.5);
  EXPECT_DOUBLE_EQ(s.x[1], 0.625);
  EXPECT_EQ(s.y[1], 3.0); // 6 N on 2 m^2
}

TEST(ScaleComparison, EjectionPressureAndModuliAgainstHandComputedValues)
{
  const coupling::ScaleComparisonSettings s = settings();
  dem::DieStudyResult                     die;
  die.rows           = {die_row("compaction", 0.6, 0.0),
                        die_row("compaction", 0.87, 2e7),
                        die_row("unloading", 0.86, 1e6)};
  die.rows[2].branch = 1;
  dem::BranchSummary determined, undetermined;
  determined.rho_max_in_die          = 0.87;
  determined.tablet.youngs_modulus   = 4e9;
  determined.tablet.poisson_ratio    = 0.2;
  determined.tablet.n_points         = 5;
  determined.ejection_pressure       = 2e5;
  undetermined.rho_max_in_die        = 0.75;
  undetermined.tablet.youngs_modulus = 1e9;
  undetermined.tablet.n_points       = 1;
  die.branches                       = {undetermined, determined};

  coupling::RveDatabaseStudyResult database;
  coupling::DpcFitRow              fit{};
  fit.relative_density = 0.8;
  fit.youngs_modulus   = 2e9;
  fit.poisson_ratio    = 0.3;
  database.fit.push_back(fit);
  fit.relative_density = 0.9;
  fit.youngs_modulus   = 8e9;
  fit.poisson_ratio    = 0.3;
  database.fit.push_back(fit);

  coupling::TabletStudyResult tablet;
  tablet.converged  = true;
  tablet.punch_area = pi * s.die_diameter * s.die_diameter / 4;
  tablet.history
    = {tablet_step(fem::TabletStage::compaction, 0.0, 0.0, 0.0),
       tablet_step(fem::TabletStage::unloading, 1e-3, 5.0, 30.0),
       tablet_step(fem::TabletStage::unloading, 1.2e-3, 0.0, 20.0)};

  coupling::ScaleComparisonInputs in;
  in.die      = &die;
  in.database = &database;
  in.tablet   = &tablet;
  const coupling::ScaleComparisonResult result
    = coupling::ScaleComparison(s).compare({0.6, 1e-2}, in);

  // E at 0.87 interpolated in the fit: 2e9 + 6e9 * 0.7 = 6.2e9; the
  // branch whose unloading curve had one point has no E and no row.
  const auto E = named(result.rows, "youngs_modulus");
  ASSERT_EQ(E.size(), 1u);
  EXPECT_EQ(E[0].reference, 4e9);
  EXPECT_NEAR(E[0].value, 6.2e9, 1e-3);
  EXPECT_NEAR(E[0].relative_difference(), 0.55, 1e-12);

  // mu F_wall / A of the last unloading step, the punch free: 0.5 * 20 N
  // over the punch area.
  const auto ejection = named(result.rows, "ejection_pressure");
  ASSERT_EQ(ejection.size(), 1u);
  EXPECT_EQ(ejection[0].relative_density, 0.87);
  EXPECT_EQ(ejection[0].reference, 2e5);
  EXPECT_NEAR(ejection[0].value, 10.0 / tablet.punch_area, 1e-6);
  EXPECT_TRUE(result.tablet_note.empty());
  // No database interior rows: the die rows have no interior.
  ASSERT_TRUE(result.interior.has_value());
  EXPECT_TRUE(result.interior->empty());

  // A punch that still carries load at the end of unloading: no value.
  tablet.history.back().forces.upper_punch_force = 1.0;
  const coupling::ScaleComparisonResult loaded
    = coupling::ScaleComparison(s).compare({0.6, 1e-2}, in);
  const auto none = named(loaded.rows, "ejection_pressure");
  ASSERT_EQ(none.size(), 1u);
  EXPECT_TRUE(std::isnan(none[0].value));
  EXPECT_FALSE(loaded.tablet_note.empty());
}

// `compax compare`: the table builder on synthetic input (linear
// interpolation is exact for linear data, relative differences by their
// definition), and the real executable on a tiny study: the promised
// columns and comparison names, every relative difference recomputed from
// its value and reference, the die and tablet studies reading back as the
// same die (diameter, fill, initial density, frictionless walls), the
// ejection pressure rebuilt from the tablet's own output, and bad input.

#include "app_test_support.h"

#include "apps/compare/compare_outputs.h"
#include "coupling/comparison_table.h"
#include "coupling/interior_comparison.h"

#include <cmath>
#include <set>
#include <tuple>

using compax::testing::AppTest;
using compax::testing::Csv;

namespace
{
  using compax::coupling::ComparisonRow;
  using compax::coupling::DensitySeries;

  constexpr double pi = 3.14159265358979323846;

  /// The columns of interior.csv the issue asks for.
  const std::vector<std::string> interior_columns
    = {"relative_density_die",
       "relative_density_interior",
       "sigma_zz_interior",
       "sigma_rr_interior",
       "sigma_zz_rve",
       "sigma_xx_rve"};

  /// The tablet's density in the rigid die, rho_0 H_0 / (H_0 - travel),
  /// the measure compare puts beside the particle die's (row k of a
  /// tablet.csv; rho_0 and H_0 the die's deposited bed).
  double
  rigid_die_density(const Csv        &tablet,
                    const std::size_t k,
                    const double      rho0,
                    const double      H0)
  {
    const double gap = H0 - tablet.column.at("upper_punch_displacement")[k]
                       - tablet.column.at("lower_punch_displacement")[k];
    return rho0 * H0 / gap;
  }

  /// A compare.csv @p value at density @p rho is the punch pressure linear
  /// between the tablet's samples (x0, y0) and (x1, y1), to 1e-9 of it
  /// (1e-6 Pa absolute).
  void
  expect_interpolated(const double value,
                      const double rho,
                      const double x0,
                      const double y0,
                      const double x1,
                      const double y1)
  {
    const double expected = y0 + (y1 - y0) * (rho - x0) / (x1 - x0);
    EXPECT_NEAR(value, expected, 1e-9 * std::abs(expected) + 1e-6) << rho;
  }

  /// A tiny study: 150 particles, a 3 mm die to 0.8, a 40-particle RVE.
  const std::string tiny = "subsection Compare\n  set FE2 = false\nend\n"
                           "subsection Die\n"
                           "  set Die diameter = 3e-3\n"
                           "  set Number of particles = 150\n"
                           "  set Final relative density = 0.8\n"
                           "  set Compaction steps = 12\n"
                           "  set Unloading points = 0.72, 0.8\n"
                           "  set Die-wall friction coefficient = 0.4\n"
                           "end\n"
                           "subsection RVE\n"
                           "  set Number of particles = 40\n"
                           "  set Shear steps = 4\n"
                           "  set Loose branches =\n"
                           "end\n"
                           "subsection Tablet\n"
                           "  set Radial cells = 1\n"
                           "  set Compaction steps = 12\n"
                           "  set Unloading steps = 6\n"
                           "end\n";
} // namespace

TEST(CompareTable, InterpolationIsExactForLinearData)
{
  // y = 3 - 7 x sampled unevenly and out of order.
  DensitySeries s;
  for (const double x : {0.81, 0.55, 0.6, 0.73, 0.9})
    {
      s.x.push_back(x);
      s.y.push_back(3.0 - 7.0 * x);
    }
  for (const double x : {0.55, 0.57, 0.6123, 0.7, 0.73, 0.8, 0.8999, 0.9})
    EXPECT_NEAR(compax::coupling::interpolate(s, x), 3.0 - 7.0 * x, 1e-14) << x;
  // Within reach of an end the end segment is extended: still exact.
  EXPECT_NEAR(compax::coupling::interpolate(s, 0.5495, 1e-3),
              3.0 - 7.0 * 0.5495,
              1e-14);
  EXPECT_NEAR(compax::coupling::interpolate(s, 0.9008, 1e-3),
              3.0 - 7.0 * 0.9008,
              1e-14);
  EXPECT_TRUE(std::isnan(compax::coupling::interpolate(s, 0.9011, 1e-3)));
  // No extrapolation.
  EXPECT_TRUE(std::isnan(compax::coupling::interpolate(s, 0.5499)));
  EXPECT_TRUE(std::isnan(compax::coupling::interpolate(s, 0.91)));
  EXPECT_TRUE(std::isnan(compax::coupling::interpolate(DensitySeries{}, 0.7)));
}

TEST(CompareTable, RowsAtTheReferenceSamplesWithRelativeDifferences)
{
  // Reference p = 2 (x - 0.5), compared q = 3 (x - 0.5) + 1 sampled
  // elsewhere: both linear, so the interpolated value is exact and the
  // relative difference is (q - p)/|p| in closed form.
  DensitySeries p, q;
  for (const double x : {0.5, 0.6, 0.7, 0.8, 0.95})
    {
      p.x.push_back(x);
      p.y.push_back(2.0 * (x - 0.5));
    }
  for (const double x : {0.52, 0.66, 0.9})
    {
      q.x.push_back(x);
      q.y.push_back(3.0 * (x - 0.5) + 1.0);
    }
  const auto rows = compax::coupling::compare_series("punch_pressure", p, q);
  // x = 0.5 has a zero reference (no relative difference): left out.
  ASSERT_EQ(rows.size(), 4u);
  for (const ComparisonRow &r : rows)
    {
      EXPECT_EQ(r.comparison, "punch_pressure");
      EXPECT_DOUBLE_EQ(r.reference, 2.0 * (r.relative_density - 0.5));
      if (r.relative_density > 0.9)
        {
          // Outside the compared samples: missing, not extrapolated.
          EXPECT_TRUE(std::isnan(r.value));
          EXPECT_TRUE(std::isnan(r.relative_difference()));
          continue;
        }
      const double q_exact = 3.0 * (r.relative_density - 0.5) + 1.0;
      EXPECT_NEAR(r.value, q_exact, 1e-14);
      EXPECT_NEAR(r.relative_difference(),
                  (q_exact - r.reference) / std::abs(r.reference),
                  1e-13);
    }
  // A negative reference divides by its magnitude.
  const ComparisonRow n{"x", 0.7, -2.0, -3.0};
  EXPECT_DOUBLE_EQ(n.relative_difference(), -0.5);
}

TEST(CompareTable, CsvHasTheIssueColumnsAndEmptyMissingCells)
{
  const auto file = std::filesystem::temp_directory_path()
                    / ("compare-table-" + std::to_string(::getpid()) + ".csv");
  compax::cli::write_comparison_csv(
    file,
    {{"youngs_modulus", 0.8, 2e9, 1.5e9},
     {"fe2_vs_database", 0.7, 1e6, std::numeric_limits<double>::quiet_NaN()}});
  const Csv csv(file);
  std::filesystem::remove(file);
  EXPECT_EQ(csv.header,
            (std::vector<std::string>{"comparison",
                                      "relative_density",
                                      "reference",
                                      "value",
                                      "relative_difference"}));
  ASSERT_EQ(csv.rows(), 2u);
  EXPECT_EQ(csv.text.at("comparison")[0], "youngs_modulus");
  EXPECT_NEAR(csv.column.at("relative_difference")[0], -0.25, 1e-12);
  EXPECT_EQ(csv.text.at("value")[1], "");
  EXPECT_EQ(csv.text.at("relative_difference")[1], "");
}

using CompareCommand = AppTest;

/// interior.csv: the RVE's compaction path (linear in rho here, with rows
/// of other paths that must be ignored) interpolated at the interior's own
/// solid fraction, not the die average; die rows without an interior, of
/// unloading or of a branch are left out; outside the RVE's range the RVE
/// cells are empty and its comparison rows have no value.
TEST_F(CompareCommand, InteriorRowsTakeTheRveAtTheInteriorDensity)
{
  // die.csv: stage, branch, relative_density, rho_interior,
  // sigma_zz_interior, sigma_rr_interior.
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<compax::dem::DieRecord> die;
  for (const auto &[stage, branch, rho, rho_i, zz, rr] : std::vector<
         std::tuple<std::string, int, double, double, double, double>>{
         {"compaction", 0, 0.55, nan, nan, nan},
         {"compaction", 0, 0.60, 0.62, -1e3, -5e2},
         {"compaction", 0, 0.70, 0.74, -2e6, -1e6},
         {"compaction", 0, 0.80, 0.83, -8e6, -5e6},
         {"unloading", 1, 0.79, 0.82, -1e6, -3e6},
         {"compaction", 0, 0.90, 0.95, -3e7, -2e7}})
    {
      compax::dem::DieRecord r;
      r.stage             = stage;
      r.branch            = branch;
      r.relative_density  = rho;
      r.rho_interior      = rho_i;
      r.sigma_zz_interior = zz;
      r.sigma_rr_interior = rr;
      die.push_back(r);
    }
  // sigma_zz = -1e8 (rho - 0.6), lateral -4e7 (rho - 0.6) on compaction.
  // database.csv: branch, path, relative_density, sigma_xx, sigma_yy,
  // sigma_zz.
  compax::coupling::RveDatabase database;
  for (const auto &[branch, path, rho, xx, yy, zz] : std::vector<
         std::tuple<int, std::string, double, double, double, double>>{
         {-1, "compaction", 0.6, 0, 0, 0},
         {0, "unloading", 0.7, 9, 9, 9},
         {-1, "compaction", 0.9, -1.4e7, -1e7, -3e7}})
    {
      compax::coupling::DatabaseRow r{};
      r.branch           = branch;
      r.path             = path;
      r.relative_density = rho;
      r.stress           = compax::dem::Vector6d::Zero();
      r.stress[0]        = xx;
      r.stress[1]        = yy;
      r.stress[2]        = zz;
      database.rows.push_back(r);
    }
  using namespace compax::cli;
  using namespace compax::coupling;
  const auto rows = compare_interior(die, database);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_DOUBLE_EQ(rows[1].relative_density_die, 0.70);
  EXPECT_DOUBLE_EQ(rows[1].relative_density_interior, 0.74);
  EXPECT_NEAR(rows[1].sigma_zz_rve, -1e8 * (0.74 - 0.6), 1e-6);
  EXPECT_NEAR(rows[1].sigma_xx_rve, -4e7 * (0.74 - 0.6), 1e-6);
  EXPECT_NEAR(rows[2].sigma_zz_rve, -1e8 * (0.83 - 0.6), 1e-6);
  EXPECT_TRUE(std::isnan(rows[3].sigma_zz_rve)); // 0.95 > 0.9

  // The 1 kPa interior is below a 5 kPa resolution: no comparison row.
  const auto  cmp = interior_comparison_rows(rows, 5e3);
  std::size_t zz = 0, ratio = 0;
  for (const ComparisonRow &c : cmp)
    {
      if (c.comparison == "interior_sigma_zz")
        ++zz;
      if (c.comparison == "interior_lateral_ratio"
          && c.relative_density == 0.83)
        {
          ++ratio;
          EXPECT_DOUBLE_EQ(c.reference, 5.0 / 8.0);
          EXPECT_NEAR(c.value, 0.4, 1e-12);
        }
    }
  EXPECT_EQ(zz, 3u);
  EXPECT_EQ(ratio, 1u);

  write_interior_csv(folder / "interior.csv", rows);
  const Csv csv(folder / "interior.csv");
  EXPECT_EQ(csv.header, interior_columns);
  ASSERT_EQ(csv.rows(), 4u);
  EXPECT_EQ(csv.text.at("sigma_zz_rve")[3], "");
}

TEST_F(CompareCommand, TinyStudyComparesTheSameDieAndMaterial)
{
  write("tiny.prm", tiny);
  const auto r = compax("compare tiny.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const auto out = folder / "out";

  const Csv table(out / "compare.csv");
  EXPECT_EQ(table.header,
            (std::vector<std::string>{"comparison",
                                      "relative_density",
                                      "reference",
                                      "value",
                                      "relative_difference"}));
  // The interior rows are interior.csv's (those whose interior carries a
  // resolved stress, 5 kPa as the die's pressure resolution): reference the
  // die interior's sigma_zz at its own density, value the RVE's there
  // (empty where the interior is denser than the RVE's compaction path
  // reached). This die is too small for an interior four diameters high
  // once compacted, so there may be none.
  const Csv interior(out / "interior.csv");
  EXPECT_EQ(interior.header, interior_columns);
  std::vector<std::size_t> loaded_interior;
  for (std::size_t j = 0; j < interior.rows(); ++j)
    if (std::abs(interior.column.at("sigma_zz_interior")[j]) >= 5e3)
      loaded_interior.push_back(j);
  std::size_t n_interior = 0;
  for (std::size_t k = 0; k < table.rows(); ++k)
    if (table.text.at("comparison")[k] == "interior_sigma_zz")
      {
        ASSERT_LT(n_interior, loaded_interior.size());
        const std::size_t j = loaded_interior[n_interior++];
        EXPECT_EQ(table.column.at("relative_density")[k],
                  interior.column.at("relative_density_interior")[j]);
        EXPECT_EQ(table.column.at("reference")[k],
                  interior.column.at("sigma_zz_interior")[j]);
        EXPECT_EQ(table.text.at("value")[k],
                  interior.text.at("sigma_zz_rve")[j]);
      }
  EXPECT_EQ(n_interior, loaded_interior.size());

  std::set<std::string> expected{"youngs_modulus",
                                 "poisson_ratio",
                                 "punch_pressure",
                                 "ejection_pressure",
                                 "fe2_vs_database"};
  if (!loaded_interior.empty())
    expected.insert({"interior_sigma_zz", "interior_lateral_ratio"});
  const std::set<std::string> names(table.text.at("comparison").begin(),
                                    table.text.at("comparison").end());
  EXPECT_EQ(names, expected);
  // relative_difference = (value - reference)/|reference| where there is a
  // value; empty where there is none (FE2 was not run).
  for (std::size_t k = 0; k < table.rows(); ++k)
    {
      const std::string name = table.text.at("comparison")[k];
      if (name == "fe2_vs_database")
        {
          EXPECT_EQ(table.text.at("value")[k], "") << k;
          continue;
        }
      if (name.rfind("interior_", 0) == 0 && table.text.at("value")[k].empty())
        continue;
      ASSERT_NE(table.text.at("value")[k], "") << name << " row " << k;
      const double ref = table.column.at("reference")[k];
      const double val = table.column.at("value")[k];
      EXPECT_NEAR(table.column.at("relative_difference")[k],
                  (val - ref) / std::abs(ref),
                  1e-9 * (1 + std::abs(val / ref)))
        << name << " row " << k;
    }

  // The same die: diameter (force over pressure is the punch area),
  // deposited bed = tablet fill (initial density, mass: rho H constant).
  const Csv    die(out / "die" / "die.csv");
  const Csv    tablet(out / "tablet-database" / "tablet.csv");
  const double area = pi * 3e-3 * 3e-3 / 4;
  for (std::size_t k = 1; k < die.rows(); ++k)
    if (die.column.at("upper_punch_pressure")[k] > 0)
      {
        EXPECT_NEAR(die.column.at("upper_punch_force")[k]
                      / die.column.at("upper_punch_pressure")[k],
                    area,
                    1e-9 * area);
        break;
      }
  std::size_t loaded = 0;
  for (std::size_t k = 0; k < tablet.rows(); ++k)
    if (tablet.column.at("upper_punch_pressure")[k] > 0)
      {
        EXPECT_NEAR(tablet.column.at("upper_punch_force")[k]
                      / tablet.column.at("upper_punch_pressure")[k],
                    area,
                    1e-9 * area);
        ++loaded;
      }
  EXPECT_GT(loaded, 5u);
  const double rho0 = die.column.at("relative_density")[0];
  const double H0   = die.column.at("punch_gap")[0];
  EXPECT_NEAR(tablet.column.at("mean_relative_density")[0], rho0, 1e-9);
  std::size_t last_compaction = 0;
  for (std::size_t k = 0; k < tablet.rows(); ++k)
    {
      if (tablet.text.at("stage")[k] != "compaction")
        continue;
      last_compaction = k;
      // Frictionless walls, as in the particle die during compaction.
      EXPECT_EQ(tablet.column.at("die_wall_friction_force")[k], 0.0);
    }
  // The punch travel takes the die's bed exactly to the final density.
  EXPECT_EQ(last_compaction, 12u);
  EXPECT_NEAR(
    (H0 - tablet.column.at("upper_punch_displacement")[last_compaction]) * 0.8,
    rho0 * H0,
    1e-9 * rho0 * H0);

  // Rows against the studies' own files.
  const Csv branches(out / "die" / "branches.csv");
  const Csv dpc(out / "tablet-database" / "database" / "dpc_table.csv");
  ASSERT_EQ(branches.rows(), 2u);
  ASSERT_EQ(dpc.rows(), 2u);
  std::size_t n_moduli = 0, n_eject = 0, n_punch = 0;
  for (std::size_t k = 0; k < table.rows(); ++k)
    {
      const std::string name = table.text.at("comparison")[k];
      const double      rho  = table.column.at("relative_density")[k];
      if (name == "youngs_modulus")
        {
          ++n_moduli;
          for (std::size_t b = 0; b < 2; ++b)
            if (std::abs(branches.column.at("rho_max_in_die")[b] - rho) < 1e-9)
              {
                EXPECT_NEAR(table.column.at("reference")[k],
                            branches.column.at("tablet_youngs_modulus")[b],
                            1e-9 * table.column.at("reference")[k]);
                // The RVE branched at the same density (within its strain
                // step), and its E is taken there on the line through the
                // two branches.
                const auto &x = dpc.column.at("relative_density");
                const auto &E = dpc.column.at("youngs_modulus");
                EXPECT_NEAR(x[b], rho, 1e-3);
                const double expected
                  = E[0] + (E[1] - E[0]) * (rho - x[0]) / (x[1] - x[0]);
                EXPECT_NEAR(table.column.at("value")[k],
                            expected,
                            1e-9 * expected);
              }
        }
      if (name == "ejection_pressure")
        {
          ++n_eject;
          EXPECT_NEAR(rho, 0.8, 1e-12);
          EXPECT_NEAR(table.column.at("reference")[k],
                      branches.column.at("ejection_pressure")[1],
                      1e-9 * table.column.at("reference")[k]);
          // mu times the residual wall force after unloading over the area.
          std::size_t last = 0;
          for (std::size_t j = 0; j < tablet.rows(); ++j)
            if (tablet.text.at("stage")[j] == "unloading")
              last = j;
          ASSERT_GT(last, 0u);
          EXPECT_EQ(tablet.column.at("upper_punch_force")[last], 0.0);
          EXPECT_NEAR(table.column.at("value")[k],
                      0.4 * tablet.column.at("die_wall_normal_force")[last]
                        / area,
                      1e-9 * table.column.at("value")[k]);
        }
      if (name == "punch_pressure")
        {
          ++n_punch;
          bool found = false;
          for (std::size_t j = 0; j < die.rows(); ++j)
            if (die.text.at("stage")[j] == "compaction"
                && std::abs(die.column.at("relative_density")[j] - rho) < 1e-9)
              {
                EXPECT_NEAR(table.column.at("reference")[k],
                            die.column.at("upper_punch_pressure")[j],
                            1e-9 * table.column.at("reference")[k]);
                found = true;
              }
          EXPECT_TRUE(found) << rho;
          // The value: the tablet's punch pressure, linear between its
          // compaction rows at the rigid die's density.
          for (std::size_t j = 1; j <= last_compaction; ++j)
            {
              const double x0 = rigid_die_density(tablet, j - 1, rho0, H0);
              const double x1 = rigid_die_density(tablet, j, rho0, H0);
              if (rho < x0 || rho > x1)
                continue;
              const double y0 = tablet.column.at("upper_punch_pressure")[j - 1];
              const double y1 = tablet.column.at("upper_punch_pressure")[j];
              expect_interpolated(
                table.column.at("value")[k], rho, x0, y0, x1, y1);
            }
        }
    }
  EXPECT_EQ(n_moduli, 2u);
  EXPECT_EQ(n_eject, 1u);
  EXPECT_GT(n_punch, 3u);
  EXPECT_TRUE(std::filesystem::exists(out / "compare.gp"));
  EXPECT_TRUE(std::filesystem::exists(out / "compare.md"));
}

TEST_F(CompareCommand, Fe2RowsAreFilledExactlyWhereTheFe2RunGot)
{
  // Tiny FE2 RVEs and no step cuts: the FE2 tablet may stop (it does at the
  // time of writing, near the jamming transition); compare must still
  // succeed, and fe2_vs_database must hold the FE2 punch pressure at every
  // database-mode density the FE2 run reached and nothing beyond.
  write(
    "fe2.prm",
    tiny.substr(tiny.find("end\n") + 4)
      + "subsection Compare\n  set FE2 = true\n"
        "  set FE2 particles per RVE = 20\n"
        "  set FE2 compaction steps = 4\n  set FE2 max step cuts = 0\nend\n");
  const auto r = compax("compare fe2.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const auto          out = folder / "out";
  const Csv           fe2(out / "tablet-fe2" / "tablet.csv");
  const Csv           db(out / "tablet-database" / "tablet.csv");
  const Csv           die(out / "die" / "die.csv");
  const Csv           table(out / "compare.csv");
  const double        rho0 = die.column.at("relative_density")[0];
  const double        H0   = die.column.at("punch_gap")[0];
  std::vector<double> x, y;
  for (std::size_t k = 0; k < fe2.rows(); ++k)
    if (fe2.text.at("stage")[k] == "compaction")
      {
        x.push_back(rigid_die_density(fe2, k, rho0, H0));
        y.push_back(fe2.column.at("upper_punch_pressure")[k]);
      }
  ASSERT_GE(x.size(), 2u);
  std::size_t rows = 0, filled = 0;
  for (std::size_t k = 0; k < table.rows(); ++k)
    {
      if (table.text.at("comparison")[k] != "fe2_vs_database")
        continue;
      ++rows;
      const double rho = table.column.at("relative_density")[k];
      // The reference is the database-mode tablet at that density.
      bool sample = false;
      for (std::size_t j = 0; j < db.rows(); ++j)
        if (db.text.at("stage")[j] == "compaction"
            && std::abs(rigid_die_density(db, j, rho0, H0) - rho) < 1e-9 * rho)
          {
            EXPECT_NEAR(table.column.at("reference")[k],
                        db.column.at("upper_punch_pressure")[j],
                        1e-9 * std::abs(table.column.at("reference")[k]));
            sample = true;
          }
      EXPECT_TRUE(sample) << rho;
      // 1e-3: samples this close count as the same density.
      const bool reached = rho <= x.back() + 1e-3;
      EXPECT_EQ(table.text.at("value")[k] != "", reached) << rho;
      if (!reached || rho > x.back())
        continue;
      ++filled;
      std::size_t j = 1;
      while (x[j] < rho)
        ++j;
      expect_interpolated(
        table.column.at("value")[k], rho, x[j - 1], y[j - 1], x[j], y[j]);
    }
  EXPECT_GT(rows, 5u);
  EXPECT_GT(filled, 0u);
  // compare.md says how the FE2 run went.
  const std::string md = read(out / "compare.md");
  EXPECT_NE(md.find("| tablet, FE2 mode | tablet-fe2/ |"), std::string::npos);
}

TEST_F(CompareCommand, FinalDensityMustBeAnUnloadingPoint)
{
  expect_prm_rejected("compare",
                      "subsection Die\n  set Final relative density = 0.85\n"
                      "  set Unloading points = 0.75, 0.8\nend\n",
                      "Die/Unloading points");
}

TEST_F(CompareCommand, OneUnloadingPointIsBadInput)
{
  expect_prm_rejected("compare",
                      "subsection Die\n  set Unloading points = 0.87\nend\n",
                      "Die/Unloading points");
}

TEST_F(CompareCommand, RvePathBelowTheDiesFinalDensityIsBadInput)
{
  // The RVE path must reach at least the die's final density (0.87 by
  // default): the tablet's table and interior.csv are compared up to it.
  expect_prm_rejected(
    "compare",
    "subsection RVE\n  set Final relative density = 0.8\nend\n",
    "entry 'RVE/Final relative density' = 0.8");
}

TEST_F(CompareCommand, BadFe2SwitchIsBadInput)
{
  expect_prm_rejected("compare",
                      "subsection Compare\n  set FE2 = maybe\nend\n",
                      "FE2");
}

TEST_F(CompareCommand, DieSettingsAreCheckedBeforeAnyRun)
{
  // A die narrower than two particle diameters: the particle study rejects
  // it, before compare writes anything.
  expect_prm_rejected("compare",
                      "subsection Die\n  set Die diameter = 5e-4\nend\n",
                      "entry 'Die/Die diameter' = 0.0005");
}

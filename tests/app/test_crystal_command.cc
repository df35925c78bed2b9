// `compax crystal` through the real executable: the built-in BCC cases
// (Hertz onsets against the geometry derived here, Hertz loads against
// closed forms), every configuration on a short path, and bad input
// (exit code 2, one line, no output folder).

#include "app_test_support.h"
#include "dem/numbers.h"

#include <cmath>

using namespace compax::testing;
using compax::dem::pi;

namespace
{
  /// Rows of a text CSV as cells.
  std::vector<std::vector<std::string>>
  rows(const std::filesystem::path &file)
  {
    std::ifstream                         in(file);
    std::vector<std::vector<std::string>> table;
    for (std::string line; std::getline(in, line);)
      {
        std::vector<std::string> cells;
        std::stringstream        s(line);
        for (std::string cell; std::getline(s, cell, ',');)
          cells.push_back(cell);
        if (!line.empty() && line.back() == ',')
          cells.push_back("");
        table.push_back(cells);
      }
    return table;
  }
} // namespace

class CrystalCommand : public AppTest
{
};

TEST_F(CrystalCommand, DefaultBccCases)
{
  const auto r = compax("crystal -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const auto table = rows(folder / "out" / "contacts.csv");
  ASSERT_EQ(table.size(), 9u); // header + 2 configurations x 2 nu x 2
  EXPECT_EQ(table[0],
            (std::vector<std::string>{"configuration",
                                      "formulation",
                                      "nu",
                                      "second_contact_density",
                                      "third_contact_density"}));
  // BCC: second neighbours at a = 4R/sqrt(3) touch when a' = 2R
  // (hydrostatic) or when the compressed edge c = 2R (die).
  const double rho0 = pi * std::sqrt(3.0) / 8, stretch = std::sqrt(3.0) / 2;
  for (std::size_t i = 1; i < table.size(); ++i)
    {
      const auto &row = table[i];
      ASSERT_EQ(row.size(), 5u);
      EXPECT_TRUE(row[2] == "0.46" || row[2] == "0.45");
      if (row[1] == "hertz")
        {
          const double expected = row[0] == "bcc-hydrostatic"
                                    ? rho0 / std::pow(stretch, 3)
                                    : rho0 / stretch;
          EXPECT_NEAR(std::stod(row[3]), expected, 1e-9) << row[0];
          EXPECT_EQ(row[4], "");
        }
      else
        EXPECT_FALSE(row[3].empty()) << row[0] << ' ' << row[2];
    }

  // Die compaction under Hertz before the second contacts: 8 contacts
  // (+-a/2, +-a/2, +-c/2) with P = n_H (2R - |d|)^{3/2}; through the cell
  // faces 2 P c/|d| (load) and 2 P a/|d| (lateral).
  const Csv    die(folder / "out" / "bcc-die.csv");
  const double R = 0.01, E = 1.85e6, nu = 0.46;
  const double n_H     = 1 / (0.75 * 2 * (1 - nu * nu) / E * std::sqrt(2 / R));
  const double a       = 4 * R / std::sqrt(3.0);
  std::size_t  checked = 0;
  for (std::size_t i = 0; i < die.rows(); ++i)
    {
      if (die.column.at("nu")[i] != 0.46)
        continue;
      const double c = a * (1 - die.column.at("strain")[i]);
      if (c <= 2 * R || c >= a)
        continue;
      const double d = std::hypot(a / std::sqrt(2.0), c / 2);
      EXPECT_NEAR(die.column.at("relative_density")[i], rho0 * a / c, 1e-9);
      const double P = n_H * std::pow(2 * R - d, 1.5);
      EXPECT_NEAR(die.column.at("hertz_load")[i], 2 * P * c / d, 1e-9 * P);
      EXPECT_NEAR(die.column.at("hertz_lateral_x")[i], 2 * P * a / d, 1e-9 * P);
      EXPECT_EQ(die.column.at("hertz_lateral_x")[i],
                die.column.at("hertz_lateral_y")[i]);
      ++checked;
    }
  EXPECT_GT(checked, 10u);
  for (const char *file : {"bcc-hydrostatic.csv",
                           "limits.csv",
                           "bcc-die_load.gp",
                           "bcc-hydrostatic_discrepancy.gp",
                           "parameters.prm"})
    EXPECT_TRUE(std::filesystem::exists(folder / "out" / file)) << file;
  EXPECT_NE(r.out.find("second contacts"), std::string::npos);
}

TEST_F(CrystalCommand, AllConfigurationsOnAShortPath)
{
  write("all.prm",
        "set Configurations = chain-1d, square-2d, cubic-3d, "
        "square-2d-rotated, hexagonal-2d, square-2d-preloaded, "
        "bcc-hydrostatic, bcc-die\n"
        "set Additional Poisson's ratios =\n"
        "set Steps = 10\nset Maximum relative density = 0.9\n");
  const auto r = compax("crystal all.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(rows(folder / "out" / "contacts.csv").size(), 17u);

  // Cubic lattice: equal lateral reactions along x and y.
  const Csv cubic(folder / "out" / "cubic-3d.csv");
  ASSERT_EQ(cubic.rows(), 11u);
  for (std::size_t i = 1; i < cubic.rows(); ++i)
    {
      const double x = cubic.column.at("nonlocal_lateral_x")[i];
      EXPECT_GT(x, 0.0);
      EXPECT_NEAR(x, cubic.column.at("nonlocal_lateral_y")[i], 1e-9 * x);
    }
  // 1-D chain: Eq. (17) to O(eps^{3/2}) at the first step (eps = 0.01).
  const Csv    chain(folder / "out" / "chain-1d.csv");
  const double nu = 0.46, k = (3 - 2 * nu) / (1 - nu), eps = 0.01;
  ASSERT_NEAR(chain.column.at("strain")[1], eps, 1e-12);
  const double D17
    = k / (2 * pi) * std::sqrt(eps) + 7 / (24 * pi * pi) * k * k * eps;
  EXPECT_NEAR(chain.column.at("discrepancy")[1],
              D17,
              2 * 5 * std::pow(k / (3 * pi), 3) * std::pow(eps, 1.5));
}

TEST_F(CrystalCommand, PrintedParametersAreAValidParameterFile)
{
  const auto printed = compax("crystal --print-parameters");
  ASSERT_EQ(printed.exit_code, 0);
  EXPECT_NE(printed.out.find("Unit: Pa"), std::string::npos);
  write("defaults.prm", printed.out);
  EXPECT_EQ(compax("crystal defaults.prm -o out").exit_code, 0);
  EXPECT_EQ(compax("crystal --help").exit_code, 0);
}

using CrystalBadInputTest = BadInputTest;

TEST_P(CrystalBadInputTest, IsRejectedWithExitCode2AndNoOutput)
{
  expect_row_rejected("crystal");
}

INSTANTIATE_TEST_SUITE_P(
  Crystal,
  CrystalBadInputTest,
  ::testing::Values(
    BadInput{"PoissonRatioHalf",
             "subsection Particle\n set Poisson's ratio = 0.5\nend\n",
             "Poisson's ratio"},
    BadInput{"PoissonRatioBelowMinusOne",
             "subsection Particle\n set Poisson's ratio = -1.2\nend\n",
             "(-1, 0.5)"},
    BadInput{"AdditionalPoissonRatio",
             "set Additional Poisson's ratios = 0.3, 0.7\n",
             "0.7"},
    BadInput{"NegativeRadius",
             "subsection Particle\n set Radius = -0.01\nend\n",
             "Radius"},
    BadInput{"UnknownConfiguration",
             "set Configurations = bcc-die, fcc-die\n",
             "fcc-die"},
    BadInput{"DensityBelowStart",
             "set Maximum relative density = 0.5\n",
             "Maximum relative density"}),
  bad_input_name);

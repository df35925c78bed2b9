// `compax rve` with Packing/Protocol = deposited (the default) and
// Solver/Consolidation: the deposit is compacted to exactly the initial
// density asked for, on the bonded path (histories at the first row) or
// with frozen histories (virgin first row); jamming is sticky; an initial
// density below the deposit's is rejected naming the entry and the range.

#include "app_test_support.h"

#include <cmath>

using compax::testing::AppTest;
using compax::testing::Csv;

namespace
{
  /// 12 printed significant digits.
  constexpr double print_tolerance = 3e-12;

  std::string
  small_cell(const std::string &consolidation,
             const std::string &unjammed = "relaxation")
  {
    return "subsection Packing\n"
           " set Number of particles = 100\n"
           " set Seed = 4\n"
           " set Initial relative density = 0.56\n"
           "end\n"
           "subsection Strain path\n"
           " set Target relative density = 0.68\n"
           " set Loading steps = 6\n"
           " set Unloading = false\n"
           "end\n"
           "subsection Output\n"
           " set Tangent interval = 0\n"
           " set Finite-difference check interval = 0\n"
           " set Snapshot interval = 0\n"
           "end\n"
           "subsection Solver\n"
           " set Consolidation = "
           + consolidation + "\n set Unjammed equilibrium = " + unjammed
           + "\nend\n";
  }
} // namespace

class RvePackingProtocol : public AppTest
{
};

TEST_F(RvePackingProtocol, DepositCompactedOnTheBondedPathOrFrozen)
{
  write("bonded.prm", small_cell("none"));
  write("frozen.prm", small_cell("frozen-history"));
  const auto b = compax("rve bonded.prm -o bonded");
  ASSERT_EQ(b.exit_code, 0) << b.err << b.out;
  const auto f = compax("rve frozen.prm -o frozen");
  ASSERT_EQ(f.exit_code, 0) << f.err << f.out;
  const Csv bonded(folder / "bonded" / "rve.csv");
  const Csv frozen(folder / "frozen" / "rve.csv");
  for (const Csv *csv : {&bonded, &frozen})
    {
      // The path starts at exactly the density asked for, as its reference.
      EXPECT_NEAR(csv->column.at("relative_density")[0], 0.56, print_tolerance);
      EXPECT_EQ(csv->column.at("eps_zz")[0], 0.0);
    }
  // Compacted from the deposit (about 0.50) to 0.56 below the jamming
  // pressure: the bonded path with relaxed loose states grew plastic radii
  // and bridges on the way (from the chains the relaxation leaves), the
  // frozen-history path left the cell virgin.
  EXPECT_LT(bonded.column.at("mean_pressure")[0], 0.5e6);
  EXPECT_GT(bonded.column.at("bonding_surface")[0], 0.0);
  EXPECT_GT(bonded.column.at("bonds")[0], 0.0);
  EXPECT_EQ(frozen.column.at("bonding_surface")[0], 0.0);
  EXPECT_EQ(frozen.column.at("bonds")[0], 0.0);
  // Balanced loose states (the default): the cell at 0.56 carries no
  // resolved force (5 kPa), so no contact has deformed or bonded.
  write("balanced.prm", small_cell("none", "balanced-relaxation"));
  const auto c = compax("rve balanced.prm -o balanced");
  ASSERT_EQ(c.exit_code, 0) << c.err << c.out;
  const Csv balanced(folder / "balanced" / "rve.csv");
  EXPECT_NEAR(balanced.column.at("relative_density")[0], 0.56, print_tolerance);
  EXPECT_LT(std::abs(balanced.column.at("mean_pressure")[0]), 5e3);
  EXPECT_EQ(balanced.column.at("bonding_surface")[0], 0.0);
  EXPECT_EQ(balanced.column.at("bonds")[0], 0.0);
  // Bonded path: jammed from the first state that carried the jamming
  // pressure on, for good.
  const auto &jammed = bonded.column.at("jammed");
  const auto &p      = bonded.column.at("mean_pressure");
  bool        once   = false;
  for (std::size_t k = 1; k < bonded.rows(); ++k)
    {
      once = once || p[k] >= 0.5e6;
      EXPECT_EQ(jammed[k], once ? 1.0 : 0.0) << "row " << k;
    }
  EXPECT_TRUE(once);
}

TEST_F(RvePackingProtocol, InitialDensityBelowTheDepositIsRejected)
{
  write("bad.prm",
        "subsection Packing\n set Initial relative density = 0.3\nend\n");
  const auto r = compax("rve bad.prm -o out");
  expect_rejected(r, "Packing/Initial relative density");
  EXPECT_NE(r.err.find("0.3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("allowed ["), std::string::npos) << r.err;
  // The gas protocol takes it.
  write("gas.prm",
        "subsection Packing\n set Initial relative density = 0.3\n"
        " set Protocol = compressed-gas\nend\n");
  EXPECT_EQ(compax("rve gas.prm --check").exit_code, 0);
}

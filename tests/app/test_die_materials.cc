// Two particle species through `compax die`: the bed compacts, unloads and
// ejects, and the number of particles of each species follows the number
// fraction within binomial scatter; inconsistent species are rejected.

#include "app_test_support.h"

#include "coupling/hdf5_archive.h"

#include <cmath>

using compax::testing::AppTest;
using compax::testing::Csv;

class DieMaterials : public AppTest
{
};

TEST_F(DieMaterials, TwoMaterialBedCompactsWithTheAskedFractions)
{
  const int    n        = 200;
  const double fraction = 0.3; // of Material (the first species)
  write("two.prm",
        "subsection Material 2\n set Young's modulus = 30e9\n"
        " set Plastic stiffness = 900e6\nend\n"
        "subsection Bonding\n set Fracture toughness 2 = 6.19e6\n"
        " set Cross fracture toughness = 2.62e6\nend\n"
        "subsection Packing\n set Number of particles = 200\n"
        " set Die diameter = 3e-3\n set Material fractions = 0.3, 0.7\nend\n"
        "subsection Protocol\n set Final relative density = 0.78\n"
        " set Compaction steps = 12\n set Unloading points = 0.78\nend\n");
  const auto r = compax("die two.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  // Species of every particle, from the saved compaction state.
  const compax::coupling::Hdf5ArchiveReader archive(
    (folder / "out" / "checkpoints" / "branch-1.h5").string());
  const auto materials = archive.read_array("bed/materials");
  ASSERT_EQ(materials.size(), std::size_t(n));
  int first = 0, second = 0;
  for (const double m : materials)
    {
      first += m == 0.0;
      second += m == 1.0;
    }
  EXPECT_EQ(first + second, n);
  // Binomial: 4 standard deviations.
  EXPECT_NEAR(double(first) / n,
              fraction,
              4 * std::sqrt(fraction * (1 - fraction) / n));
  EXPECT_NE(r.out.find(std::to_string(second) + " of material 2"),
            std::string::npos)
    << r.out;

  // It compacted to the final density with the punches in balance.
  const Csv   die(folder / "out" / "die.csv");
  const auto &rho   = die.column.at("relative_density");
  const auto &upper = die.column.at("upper_punch_force");
  const auto &lower = die.column.at("lower_punch_force");
  EXPECT_NEAR(*std::max_element(rho.begin(), rho.end()), 0.78, 1e-6);
  const double peak = *std::max_element(upper.begin(), upper.end());
  ASSERT_GT(peak, 0.0);
  for (std::size_t i = 0; i < die.rows(); ++i)
    EXPECT_NEAR(upper[i], lower[i], 1e-4 * peak) << "row " << i;
  EXPECT_EQ(Csv(folder / "out" / "branches.csv").rows(), 1u);
}

TEST_F(DieMaterials, FractionsThatDoNotSumToOneAreRejected)
{
  expect_prm_rejected(
    "die",
    "subsection Packing\n set Material fractions = 0.3, 0.6\nend\n",
    "Material fractions");
}

TEST_F(DieMaterials, ThreeFractionsAreRejected)
{
  expect_prm_rejected(
    "die",
    "subsection Packing\n set Material fractions = 0.2, 0.3, 0.5\nend\n",
    "Material fractions");
}

TEST_F(DieMaterials, SecondSpeciesOfAnotherRadiusIsRejected)
{
  expect_prm_rejected(
    "die",
    "subsection Material 2\n set Radius = 100e-6\nend\n"
    "subsection Packing\n set Material fractions = 0.5, 0.5\nend\n",
    "Material 2/Radius");
}

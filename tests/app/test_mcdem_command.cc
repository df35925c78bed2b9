// `compax mcdem` and `compax calibrate` through the real executable on
// short runs: the CSV columns, conservation of the particle volume in the
// relative density, plate stress against the particles' Love-Weber stress
// (quasi-static equilibrium), plastic unloading, beta = 0 below beta > 0
// (Giannis 2021 Fig. 8), the RVE-size study, a calibration from a CSV,
// and rejected input.

#include "app_test_support.h"

#include <algorithm>
#include <cmath>

using compax::testing::AppTest;
using compax::testing::Csv;
using compax::testing::expect_columns;

namespace
{
  /// A short run: 0.6 mm MCC-A cell to 35% strain, then unloading.
  std::string
  short_run(const double beta, const std::string &extra = "")
  {
    return "subsection Multi-contact law\n  set Multi-contact prefactor = "
           + std::to_string(beta)
           + "\nend\nsubsection Protocol\n  set Target strain = 0.35\n"
             "  set Strain rate = 100\nend\nsubsection Numerics\n"
             "  set Mass scaling = 100\nend\n"
           + extra;
  }
} // namespace

class McdemCommand : public AppTest
{
};

TEST_F(McdemCommand, CompactionCurveIsConsistent)
{
  write("run.prm", short_run(1.3));
  const auto r = compax("mcdem run.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv csv(folder / "out" / "mcdem.csv");
  expect_columns(csv,
                 {"time",
                  "stage",
                  "strain",
                  "stress_zz",
                  "relative_density",
                  "kinetic_energy",
                  "elastic_energy"});
  EXPECT_TRUE(std::filesystem::exists(folder / "out" / "mcdem.png"));
  EXPECT_NE(r.out.find("particle-steps/s"), std::string::npos);

  const auto &stage = csv.column.at("stage"), &e = csv.column.at("strain"),
             &s   = csv.column.at("stress_zz"),
             &lw  = csv.column.at("stress_zz_bulk"),
             &rho = csv.column.at("relative_density");
  ASSERT_GT(csv.rows(), 50u);
  // Rigid particles in a shrinking box: rho (1 - strain) is constant.
  for (std::size_t k = 0; k < csv.rows(); ++k)
    EXPECT_NEAR(rho[k] * (1.0 - e[k]), rho[0], 1e-9 * rho[0]);
  EXPECT_NEAR(rho[0], 0.59, 0.02);
  // Quasi-static: the plates carry what the contact network carries.
  double peak = 0.0;
  for (std::size_t k = 0; k < csv.rows(); ++k)
    if (stage[k] == 1 && e[k] > 0.15)
      {
        EXPECT_NEAR(s[k], lw[k], 0.1 * lw[k]) << "strain " << e[k];
        EXPECT_GE(s[k], 0.9 * peak); // loading stiffens
        peak = std::max(peak, s[k]);
      }
  EXPECT_GT(peak, 1e6);
  // Decompression ends when the plate stress vanishes, at a plastic
  // (residual) strain close to the peak strain: k2/k1 = 120.
  ASSERT_EQ(stage.back(), 2.0);
  EXPECT_LE(s.back(), 0.0 + 1e-6 * peak);
  EXPECT_GT(e.back(), 0.3);
  EXPECT_LT(e.back(), 0.35);
}

TEST_F(McdemCommand, ConventionalDemUnderestimatesTheStress)
{
  write("mc.prm",
        short_run(1.3, "subsection Protocol\n  set Decompress = false\nend\n"));
  write("dem.prm",
        short_run(0.0, "subsection Protocol\n  set Decompress = false\nend\n"));
  ASSERT_EQ(compax("mcdem mc.prm -o mc").exit_code, 0);
  ASSERT_EQ(compax("mcdem dem.prm -o dem").exit_code, 0);
  const Csv mc(folder / "mc" / "mcdem.csv"),
    conventional(folder / "dem" / "mcdem.csv");
  ASSERT_EQ(mc.rows(), conventional.rows());
  // Same packing (same seed), so the curves start together and part at
  // high strain (Fig. 8: the multi-contact effect dominates above ~0.2).
  EXPECT_NEAR(mc.column.at("stress_zz")[1],
              conventional.column.at("stress_zz")[1],
              0.05 * mc.column.at("stress_zz")[1]);
  EXPECT_GT(mc.column.at("stress_zz").back(),
            1.1 * conventional.column.at("stress_zz").back());
}

TEST_F(McdemCommand, RveSizeStudyWritesOneCurvePerCell)
{
  write(
    "rve.prm",
    "subsection Cell\n  set Cell sizes = 0.5e-3, 0.7e-3\nend\n"
    "subsection Protocol\n  set Target strain = 0.15\n  set Strain rate = 200\n"
    "  set Decompress = false\nend\nsubsection Numerics\n"
    "  set Mass scaling = 100\nend\n");
  const auto r = compax("mcdem rve.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv study(folder / "out" / "rve_study.csv");
  ASSERT_EQ(study.rows(), 2u);
  // Same statistics: both cells are filled to the packing density (to
  // within the volume of one particle, drawn closest) from the same
  // distribution, the larger with more particles.
  const auto &n = study.column.at("particles");
  EXPECT_GT(n[1], 1.5 * n[0]);
  for (const double rho : study.column.at("initial_density"))
    EXPECT_NEAR(rho, 0.59, 0.05);
  EXPECT_TRUE(std::filesystem::exists(folder / "out" / "mcdem_cell_2.csv"));
}

TEST_F(McdemCommand, CalibrateFitsBetaToAMeasuredCsv)
{
  // "Measured": a loading curve of the code on packing seed 7 (beta 1.3).
  write("measure.prm",
        short_run(1.3,
                  "subsection Cell\n  set Seed = 7\nend\n"
                  "subsection Protocol\n  set Decompress = false\nend\n"));
  ASSERT_EQ(compax("mcdem measure.prm -o measured").exit_code, 0);
  write("fit.prm",
        short_run(1.3,
                  "subsection Protocol\n  set Decompress = false\nend\n"
                  "subsection Calibration\n"
                  "  set Measured curve = measured/mcdem.csv\n"
                  "  set Fitted parameters = beta\n"
                  "  set Initial values = 0.2\n  set Lower bounds = 0\n"
                  "  set Upper bounds = 3\n  set Target R2 = 0.9\n"
                  "  set Maximum simulations = 6\nend\n"));
  const auto r = compax("calibrate fit.prm -o fit");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const Csv history(folder / "fit" / "calibration.csv");
  ASSERT_GE(history.rows(), 1u);
  EXPECT_GT(*std::max_element(history.column.at("r2").begin(),
                              history.column.at("r2").end()),
            0.9);
  EXPECT_TRUE(std::filesystem::exists(folder / "fit" / "calibrated_law.prm"));
  EXPECT_TRUE(std::filesystem::exists(folder / "fit" / "calibration_fit.csv"));
}

TEST_F(McdemCommand, RejectsACellNarrowerThanTheLargestParticle)
{
  write("bad.prm", "subsection Cell\n  set Cell sizes = 0.3e-3\nend\n");
  expect_refused_without_output(compax("mcdem bad.prm -o out"), {"Cell sizes"});
  const auto printed = compax("mcdem --print-parameters");
  ASSERT_EQ(printed.exit_code, 0);
  write("defaults.prm", printed.out);
  EXPECT_EQ(compax("calibrate --print-parameters").exit_code, 0);
}

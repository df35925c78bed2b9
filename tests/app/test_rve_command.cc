// `compax rve` through the real executable on small cells: the columns the
// issue promises; the strain path against its closed form (uniaxial:
// eps_xx = eps_yy = 0 exactly and eps_zz = ln(rho_0/rho) by mass
// conservation; hydrostatic: equal normal strains; csv: the product of the
// increments); equal density steps; unloading to a vanishing axial stress;
// the condensed tangent against finite differences; resume = uninterrupted;
// the size study's spread recomputed from its table; bad input.

#include "app_test_support.h"

#include <cmath>

using compax::testing::AppTest;
using compax::testing::Csv;
using compax::testing::expect_columns;

namespace
{
  /// CsvWriter prints 12 significant digits: a logarithm of a ratio of two
  /// printed densities, and a printed strain of magnitude < 1, each carry a
  /// relative rounding of 5e-13, so 3e-12 bounds the difference of the two
  /// sides of an exact identity read back from the file.
  constexpr double print_tolerance = 3e-12;

  const std::string small_uniaxial
    = "subsection Packing\n"
      " set Number of particles = 100\n"
      " set Seed = 4\n"
      "end\n"
      "subsection Strain path\n"
      " set Target relative density = 0.74\n"
      " set Loading steps = 10\n"
      " set Unloading strain step = 3e-3\n"
      "end\n"
      "subsection Output\n"
      " set Tangent interval = 2\n"
      " set Finite-difference check interval = 2\n"
      " set Snapshot interval = 5\n"
      "end\n";

  /// The condensed tangent equals central finite differences of the cell
  /// (at trial states half a step along the path, histories frozen) at
  /// every step that checked it, and some step did.
  void
  expect_tangent_equals_finite_differences(const Csv &moduli)
  {
    std::size_t checked = 0;
    for (std::size_t i = 0; i < moduli.rows(); ++i)
      if (!moduli.text.at("tangent_fd_error")[i].empty())
        {
          EXPECT_LT(moduli.column.at("tangent_fd_error")[i], 1e-4)
            << "step " << moduli.column.at("step")[i];
          ++checked;
        }
    EXPECT_GT(checked, 0u);
  }
} // namespace

class RveCommand : public AppTest
{
};

TEST_F(RveCommand, UniaxialPathFollowsMassConservationAndUnloads)
{
  write("small.prm", small_uniaxial);
  const auto r = compax("rve small.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;

  const Csv rve(folder / "out" / "rve.csv");
  expect_columns(rve,
                 {"step",
                  "stage",
                  "relative_density",
                  "eps_xx",
                  "eps_yy",
                  "eps_zz",
                  "eps_yz",
                  "eps_xz",
                  "eps_xy",
                  "sigma_xx",
                  "sigma_yy",
                  "sigma_zz",
                  "sigma_xy",
                  "sigma_yz",
                  "sigma_xz",
                  "mean_pressure",
                  "coordination_number",
                  "bonding_surface",
                  "bonds_formed",
                  "bonds_broken",
                  "iterations",
                  "residual"});
  const Csv moduli(folder / "out" / "moduli.csv");
  expect_columns(moduli,
                 {"step",
                  "relative_density",
                  "E",
                  "nu",
                  "E_p",
                  "nu_p",
                  "E_z",
                  "nu_zp",
                  "G_zp",
                  "C11",
                  "C33",
                  "C12",
                  "C13",
                  "C44",
                  "C33_affine",
                  "tangent_fd_error"});

  const auto  &rho   = rve.column.at("relative_density");
  const auto  &stage = rve.text.at("stage");
  const double rho0  = rho.front();
  EXPECT_NEAR(rho0, 0.55, 1e-9);
  std::size_t loading = 0, unloading = 0;
  for (std::size_t i = 0; i < rve.rows(); ++i)
    {
      // F = diag(1, 1, rho_0/rho): the lateral and shear strains vanish
      // exactly and eps_zz = ln(rho_0 / rho) (the mass of the cell is fixed).
      for (const char *c : {"eps_xx", "eps_yy", "eps_yz", "eps_xz", "eps_xy"})
        EXPECT_EQ(rve.column.at(c)[i], 0.0) << c << " row " << i;
      EXPECT_NEAR(rve.column.at("eps_zz")[i],
                  std::log(rho0 / rho[i]),
                  print_tolerance)
        << "row " << i;
      if (stage[i] == "loading")
        {
          // Equal density steps from rho_0 to the target.
          EXPECT_NEAR(rho[i], rho0 + (0.74 - rho0) * loading / 10.0, 1e-11)
            << "row " << i;
          ++loading;
        }
      else
        {
          ASSERT_EQ(stage[i], "unloading");
          EXPECT_LT(rho[i], rho[i - 1]) << "row " << i;
          ++unloading;
        }
    }
  EXPECT_EQ(loading, 11u);
  ASSERT_GT(unloading, 1u);
  // Loaded states carry compression; unloading stops at the first state
  // whose axial stress no longer is compressive.
  const auto &szz = rve.column.at("sigma_zz");
  EXPECT_LT(szz[10], 0.0);
  for (std::size_t i = 11; i + 1 < rve.rows(); ++i)
    EXPECT_LT(szz[i], 0.0) << "row " << i;
  EXPECT_GE(szz.back(), 0.0);

  expect_tangent_equals_finite_differences(moduli);

  // Snapshots listed in the collection exist.
  const std::string pvd = read(folder / "out" / "snapshots.pvd");
  EXPECT_NE(pvd.find("snapshots/rve-0.vtu"), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_regular_file(folder / "out" / "snapshots"
                                               / "rve-5.vtu"));
}

TEST_F(RveCommand, HydrostaticPathHasEqualNormalStrains)
{
  write("hydro.prm",
        "subsection Packing\n set Number of particles = 80\nend\n"
        "subsection Strain path\n set Path = hydrostatic\n"
        " set Target relative density = 0.7\n set Loading steps = 5\n"
        " set Unloading = false\nend\n"
        "subsection Output\n set Snapshot interval = 0\nend\n");
  const auto r = compax("rve hydro.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const Csv   rve(folder / "out" / "rve.csv");
  const auto &rho = rve.column.at("relative_density");
  ASSERT_EQ(rve.rows(), 6u);
  for (std::size_t i = 0; i < rve.rows(); ++i)
    {
      const double e = rve.column.at("eps_zz")[i];
      EXPECT_EQ(rve.column.at("eps_xx")[i], e) << "row " << i;
      EXPECT_EQ(rve.column.at("eps_yy")[i], e) << "row " << i;
      EXPECT_EQ(rve.column.at("eps_xy")[i], 0.0) << "row " << i;
      // Volume ratio rho_0/rho = exp(tr eps).
      EXPECT_NEAR(3 * e, std::log(rho.front() / rho[i]), print_tolerance);
    }
  EXPECT_GT(rve.column.at("mean_pressure").back(), 0.0);
}

TEST_F(RveCommand, CsvPathAppliesTheIncrements)
{
  // Axial increments e_k on the current configuration: F_zz = prod (1 +
  // e_k), so eps_zz = sum ln(1 + e_k); the other components stay zero.
  write("path.csv",
        "# a comment\neps_xy,eps_xx,eps_yy,eps_zz,eps_yz,eps_xz\n"
        "0,0,0,-0.03,0,0\n0,0,0,-0.05,0,0\n0,0,0,-0.04,0,0\n");
  write("csv.prm",
        "subsection Packing\n set Number of particles = 60\nend\n"
        "subsection Strain path\n set Path = csv\n"
        " set Strain increments file = path.csv\n set Unloading = false\n"
        "end\nsubsection Output\n set Snapshot interval = 0\nend\n");
  const auto r = compax("rve csv.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const Csv rve(folder / "out" / "rve.csv");
  ASSERT_EQ(rve.rows(), 4u);
  const double e[3] = {-0.03, -0.05, -0.04};
  double       sum  = 0.0;
  for (std::size_t i = 0; i < 4; ++i)
    {
      if (i > 0)
        sum += std::log1p(e[i - 1]);
      EXPECT_NEAR(rve.column.at("eps_zz")[i], sum, print_tolerance);
      EXPECT_EQ(rve.column.at("eps_xx")[i], 0.0);
      EXPECT_EQ(rve.column.at("eps_xz")[i], 0.0);
      EXPECT_NEAR(rve.column.at("relative_density")[i],
                  rve.column.at("relative_density")[0] * std::exp(-sum),
                  1e-11);
    }
}

TEST_F(RveCommand, ResumedRunEqualsTheUninterruptedRun)
{
  const std::string base = small_uniaxial
                           + "subsection Checkpoints\n"
                             " set Checkpoint interval = 3\n";
  write("whole.prm", base + "end\n");
  write("first.prm", base + " set Stop after steps = 7\nend\n");
  ASSERT_EQ(compax("rve whole.prm -o whole").exit_code, 0);
  const auto first = compax("rve first.prm -o first");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(Csv(folder / "first" / "rve.csv").rows(), 8u);
  write("second.prm",
        base + " set Resume from = first/checkpoints/rve.h5\nend\n");
  const auto second = compax("rve second.prm -o second");
  ASSERT_EQ(second.exit_code, 0) << second.err << second.out;

  for (const char *file : {"rve.csv", "moduli.csv"})
    {
      const Csv a(folder / "whole" / file), b(folder / "second" / file);
      ASSERT_EQ(a.rows(), b.rows()) << file;
      ASSERT_EQ(a.header, b.header) << file;
      for (const auto &name : a.header)
        {
          if (name == "step_seconds" || name == "tangent_seconds")
            continue;
          for (std::size_t i = 0; i < a.rows(); ++i)
            EXPECT_EQ(a.text.at(name)[i], b.text.at(name)[i])
              << file << " " << name << " row " << i;
        }
    }
}

TEST_F(RveCommand, SizeStudyReportsTheSpreadBetweenSizes)
{
  write("sizes.prm",
        "subsection Strain path\n set Target relative density = 0.7\n"
        " set Loading steps = 5\n set Unloading = false\nend\n"
        "subsection Output\n set Tangent interval = 0\n"
        " set Snapshot interval = 0\nend\n"
        "subsection Size study\n set Cell sizes = 50, 80\nend\n");
  const auto r = compax("rve sizes.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const Csv study(folder / "out" / "rve_size_study.csv");
  ASSERT_EQ(study.rows(), 2u);
  EXPECT_EQ(study.column.at("particle_count")[0], 50);
  EXPECT_EQ(study.column.at("particle_count")[1], 80);
  for (const char *c : {"cell_edge_over_mean_diameter",
                        "sigma_zz_loaded",
                        "E_loaded",
                        "nu_loaded",
                        "E_end"})
    ASSERT_TRUE(study.has(c)) << c;
  // Monodisperse cells at equal density: edge / diameter = (pi N / (6
  // rho_0))^(1/3).
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_NEAR(study.column.at("cell_edge_over_mean_diameter")[i],
                std::cbrt(M_PI * study.column.at("particle_count")[i]
                          / (6 * 0.55)),
                1e-9);
  const Csv spread(folder / "out" / "rve_size_spread.csv");
  bool      found = false;
  for (std::size_t q = 0; q < spread.rows(); ++q)
    if (spread.text.at("quantity")[q] == "sigma_zz_loaded")
      {
        const double a = study.column.at("sigma_zz_loaded")[0];
        const double b = study.column.at("sigma_zz_loaded")[1];
        EXPECT_NEAR(spread.column.at("spread")[q],
                    std::abs(a - b) / std::abs(0.5 * (a + b)),
                    1e-9);
        found = true;
      }
  EXPECT_TRUE(found);
  EXPECT_TRUE(
    std::filesystem::is_regular_file(folder / "out" / "size-50" / "rve.csv"));
}

TEST_F(RveCommand, TargetBelowTheInitialDensityIsRejected)
{
  expect_prm_rejected(
    "rve",
    "subsection Strain path\n set Target relative density = 0.5\nend\n",
    "Strain path/Target relative density");
}

TEST_F(RveCommand, CellNarrowerThanAParticleIsRejected)
{
  expect_prm_rejected("rve",
                      "subsection Packing\n set Number of particles = 3\nend\n",
                      "Packing/Number of particles");
}

TEST_F(RveCommand, StrainFileWithoutAColumnIsRejected)
{
  expect_prm_rejected("rve",
                      "subsection Strain path\n set Path = csv\n"
                      " set Strain increments file = bad.prm\nend\n",
                      "Strain path/Strain increments file");
}

TEST_F(RveCommand, SingleCellSizeIsRejected)
{
  expect_prm_rejected("rve",
                      "subsection Size study\n set Cell sizes = 100\nend\n",
                      "Size study/Cell sizes");
}

TEST_F(RveCommand, MissingCheckpointIsRejected)
{
  expect_prm_rejected(
    "rve",
    "subsection Checkpoints\n set Resume from = nowhere.h5\nend\n",
    "Checkpoints/Resume from");
}

/// A registered law runs in `compax rve` through Contact/Contact law alone
/// (the Walton-Braun spring): the path keeps its closed form
/// (eps_zz = ln(rho_0/rho), mass conservation), the loaded cell is in
/// compression, and the condensed tangent equals central differences.
TEST_F(RveCommand, WaltonBraunLawRunsThroughTheRegistry)
{
  write("wb.prm",
        small_uniaxial
          + "subsection Contact\n  set Contact law = walton-braun\nend\n");
  const auto r = compax("rve wb.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const Csv    rve(folder / "out" / "rve.csv");
  const auto  &rho  = rve.column.at("relative_density");
  const double rho0 = rho.front();
  for (std::size_t i = 0; i < rve.rows(); ++i)
    EXPECT_NEAR(rve.column.at("eps_zz")[i],
                std::log(rho0 / rho[i]),
                print_tolerance)
      << "row " << i;
  EXPECT_LT(rve.column.at("sigma_zz")[10], 0.0);
  for (const double s : rve.column.at("bonding_surface"))
    EXPECT_EQ(s, 0.0);
  expect_tangent_equals_finite_differences(Csv(folder / "out" / "moduli.csv"));
}

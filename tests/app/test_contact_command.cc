// `compax contact` through the real executable: the built-in Du et al. case
// against closed forms of Gonzalez 2018, the documented defaults as a valid
// .prm, and the bad inputs of the foundation issue (exit code 2, a message
// naming entry, value and range, no output folder).

#include "app_test_support.h"
#include "dem/numbers.h"

#include <cmath>

using namespace compax::testing;
using compax::dem::pi;

class ContactCommand : public AppTest
{
};

TEST_F(ContactCommand, DefaultDuCaseMatchesClosedForms)
{
  const auto r = compax("contact -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv csv(folder / "out" / "contact.csv");
  EXPECT_EQ(
    csv.header,
    (std::vector<std::string>{
      "step", "gamma", "force", "contact_radius", "a_p", "a_B", "stiffness"}));
  ASSERT_EQ(csv.rows(), 801u);

  // Sphere R = 1.3 um on a rigid flat: R* = R, E* = E/(1-nu^2),
  // n_p = pi k R^{-1/m} kappa.
  const double R = 1.3e-6, E = 233e9 / (1 - 0.09), kappa = 12.1e9, m = 1.79;
  const double K = 0.48e6, gamma_max = 28.2e-9;
  const double c2 = 1.43 * std::exp(-0.97 / m);
  const double n_p
    = pi * 3 * std::pow(6.0, -1 / m) * std::pow(R, -1 / m) * kappa;
  const double a_p = std::sqrt(2 * c2 * R * gamma_max);

  const auto  &force = csv.column.at("force");
  const auto  &gamma = csv.column.at("gamma");
  const auto  &a_B   = csv.column.at("a_B");
  const double peak  = *std::max_element(force.begin(), force.end());
  EXPECT_NEAR(peak, n_p * std::pow(a_p, 2 + 1 / m), 1e-9 * peak);
  EXPECT_NEAR(csv.column.at("a_p").back(), a_p, 1e-9 * a_p);

  // The bond breaks within one step of the closed form of Sec. 3.
  const double gamma_b
    = gamma_max - 3 * n_p * std::pow(a_p, 1 + 1 / m) / (4 * E);
  std::size_t broken
    = std::max_element(gamma.begin(), gamma.end()) - gamma.begin();
  while (broken < a_B.size() && a_B[broken] > 0)
    ++broken;
  ASSERT_LT(broken, a_B.size());
  const double step = (gamma_max - 14e-9) / 400;
  EXPECT_LE(gamma[broken], gamma_b + 1e-12);
  EXPECT_GT(gamma[broken], gamma_b - step);

  // The most tensile force is printed with the bridge force scale of Eq. 4.
  const double pull_off = *std::min_element(force.begin(), force.end());
  EXPECT_LT(pull_off, 0.0);
  EXPECT_GT(pull_off, -2 * K * std::sqrt(pi) * std::pow(a_p, 1.5));
  EXPECT_NE(r.out.find("pull-off"), std::string::npos);
  EXPECT_NE(r.out.find("bond broken at gamma"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(folder / "out" / "contact.gp"));
}

TEST_F(ContactCommand, PrintedParametersAreAValidParameterFile)
{
  const auto printed = compax("contact --print-parameters");
  ASSERT_EQ(printed.exit_code, 0);
  EXPECT_NE(printed.out.find("Unit: Pa"), std::string::npos);
  write("defaults.prm", printed.out);
  const auto r = compax("contact defaults.prm -o out");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(compax("--help").exit_code, 0);
  EXPECT_EQ(compax("contact --help").exit_code, 0);
}

TEST_F(ContactCommand, HertzSphereSphereOfTwoMaterials)
{
  write("hertz.prm",
        "set Law = hertz\nset Geometry = sphere-sphere\n"
        "subsection Particle 1\n set Radius = 1e-3\n"
        " set Young's modulus = 1e9\n set Poisson's ratio = 0.3\nend\n"
        "subsection Particle 2\n set Radius = 2e-3\n"
        " set Young's modulus = 3e9\n set Poisson's ratio = 0.2\nend\n"
        "subsection Overlap history\n set Turning points = 0, 1e-5\n"
        " set Steps per segment = 10\nend\n");
  const auto r = compax("contact hertz.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv    csv(folder / "out" / "contact.csv");
  const double R = 1 / (1 / 1e-3 + 1 / 2e-3);
  const double E = 1 / ((1 - 0.09) / 1e9 + (1 - 0.04) / 3e9);
  const double P = 4.0 / 3.0 * E * std::sqrt(R) * std::pow(1e-5, 1.5);
  EXPECT_NEAR(csv.column.at("force").back(), P, 1e-9 * P);
}

using ContactBadInput = BadInputTest;

TEST_P(ContactBadInput, IsRejectedWithExitCode2AndNoOutput)
{
  expect_row_rejected("contact");
}

INSTANTIATE_TEST_SUITE_P(
  FoundationIssue,
  ContactBadInput,
  ::testing::Values(
    BadInput{"unknown_entry", "set Colour = blue\n", "Colour"},
    BadInput{"malformed_number",
             "subsection Particle 1\n set Young's modulus = 5e9x\nend\n",
             "5e9x"},
    BadInput{"zero_modulus",
             "subsection Particle 1\n set Young's modulus = 0\nend\n",
             "(0, inf)"},
    BadInput{"negative_modulus",
             "subsection Particle 2\n set Young's modulus = -1e9\nend\n",
             "Young's modulus"},
    BadInput{"poisson_half",
             "subsection Particle 1\n set Poisson's ratio = 0.5\nend\n",
             "(-1, 0.5)"},
    BadInput{"poisson_minus_one",
             "subsection Particle 1\n set Poisson's ratio = -1\nend\n",
             "(-1, 0.5)"},
    BadInput{"exponent_below_one",
             "subsection Particle 1\n set Plastic exponent = 0.9\nend\n",
             "Plastic exponent"},
    BadInput{"zero_regularization",
             "subsection Bonding\n set Regularization parameter = 0\nend\n",
             "Regularization parameter"},
    BadInput{"zero_radius",
             "subsection Particle 1\n set Radius = 0\nend\n",
             "Radius"},
    BadInput{"history_not_numbers",
             "subsection Overlap history\n set Turning points = 0, "
             "1e-9, up\nend\n",
             "Turning points"},
    BadInput{"different_exponents",
             "set Geometry = sphere-sphere\nsubsection Particle 2\n"
             " set Plastic exponent = 3\nend\n",
             "Plastic exponent"}),
  bad_input_name);

TEST_F(ContactCommand, MissingFileIsRejected)
{
  expect_refused_without_output(compax("contact nowhere.prm -o out"),
                                {"nowhere.prm"});
}

TEST_F(ContactCommand, EveryLawRunsAndMulticontactReducesToHertz)
{
  const std::string path = "subsection Overlap history\n set Turning points "
                           "= 0, 28.2e-9, 5e-9, 20e-9\n set Steps per "
                           "segment = 50\nend\n";
  write("hertz.prm", "set Law = hertz\n" + path);
  write("multi.prm",
        "set Law = multicontact-adhesive\n" + path
          + "subsection Multi-contact\n set Unloading stiffness ratio = 1\n"
            " set Adhesion stiffness ratio = 0\n set Prefactor = 0\nend\n");
  write("nonlocal.prm", "set Law = nonlocal-hertz\n" + path);
  ASSERT_EQ(compax("contact hertz.prm -o hertz").exit_code, 0);
  ASSERT_EQ(compax("contact multi.prm -o multi").exit_code, 0);
  ASSERT_EQ(compax("contact nonlocal.prm -o nonlocal").exit_code, 0);
  const Csv hertz(folder / "hertz" / "contact.csv");
  const Csv multi(folder / "multi" / "contact.csv");
  const Csv nonlocal(folder / "nonlocal" / "contact.csv");
  for (std::size_t i = 0; i < hertz.rows(); ++i)
    {
      const double P = hertz.column.at("force")[i];
      EXPECT_NEAR(multi.column.at("force")[i], P, 1e-9 * P);
      // The nonlocal overlap of Tatara's configuration only stiffens.
      EXPECT_GE(nonlocal.column.at("force")[i], P);
    }
}

TEST_F(ContactCommand, WaltonBraunFollowsItsLoadingUnloadingAndAdhesiveBranches)
{
  // Sphere on a flat, R = 10 um, k1 = 100 N/m, k2_max = 4 k1, kc = k1/2,
  // phi_F = 0.05: delta* = 4/3 * 0.05 * 2R = 1.333 um. Loaded to 1 um,
  // unloaded to 0.2 um, reloaded to 0.8 um; every sample is a converged
  // state. The branches, written out here from Luding's definition:
  // k2 = k1 + 3 k1 min(1, d_max/d*), d_0 = (1 - k1/k2) d_max, loading
  // k1 d, un/reloading k2 (d - d_0), adhesion -kc d below
  // d_min = (k2 - k1)/(k2 + kc) d_max.
  write("wb.prm",
        "set Law = walton-braun\nset Geometry = sphere-wall\n"
        "subsection Particle 1\n set Radius = 10e-6\nend\n"
        "subsection Walton-Braun\n set Loading stiffness = 100\n"
        " set Unloading stiffness ratio = 4\n set Adhesion stiffness ratio = "
        "0.5\n set Plasticity depth = 0.05\nend\n"
        "subsection Overlap history\n set Turning points = 0, 1e-6, 0.2e-6, "
        "0.8e-6\n set Steps per segment = 40\nend\n");
  ASSERT_EQ(compax("contact wb.prm -o wb").exit_code, 0);
  const Csv    csv(folder / "wb" / "contact.csv");
  const double k1 = 100, k2_max = 400, kc = 50, limit = 4.0 / 3.0 * 0.05 * 2e-5;
  double       d_max    = 0.0;
  int          adhesive = 0, unloading = 0;
  for (std::size_t i = 0; i < csv.rows(); ++i)
    {
      const double d     = csv.column.at("gamma")[i];
      const double k2    = k1 + (k2_max - k1) * std::min(1.0, d_max / limit);
      const double d0    = (1 - k1 / k2) * d_max;
      const double d_min = (k2 - k1) / (k2 + kc) * d_max;
      double       P     = 0.0;
      if (d >= d_max)
        P = k1 * d;
      else if (d > d_min)
        P = k2 * (d - d0), ++unloading;
      else if (d > 0)
        P = -kc * d, ++adhesive;
      EXPECT_NEAR(csv.column.at("force")[i], P, 1e-5 * std::abs(P) + 1e-12)
        << "row " << i << ", gamma " << d;
      d_max = std::max(d_max, d);
      // The law's one internal variable, after the converged state.
      EXPECT_DOUBLE_EQ(csv.column.at("delta_max")[i], d_max) << "row " << i;
    }
  EXPECT_GT(unloading, 0);
  EXPECT_GT(adhesive, 0);
}

TEST_F(ContactCommand, EveryShippedParameterFileIsValid)
{
  // apps/parameters/<command>_*.prm must parse and pass the command's checks.
  int checked = 0;
  for (const auto &entry : std::filesystem::directory_iterator(
         std::filesystem::path(COMPAX_SOURCE_DIR) / "apps" / "parameters"))
    {
      if (entry.path().extension() != ".prm")
        continue; // data files that .prm files name (e.g. strain paths)
      const std::string name    = entry.path().filename().string();
      const std::string command = name.substr(0, name.find('_'));
      const auto        r
        = compax(command + " '" + entry.path().string() + "' --check");
      EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
      ++checked;
    }
  EXPECT_GE(checked, 3);
}

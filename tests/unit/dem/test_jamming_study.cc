// The jamming study's pieces against independent values: the Eq. (14) fit
// of a compaction path uses exactly the jammed states (closed-form data
// recovered, unjammed and branch rows ignored), and K_Ic = 0 removes the
// bridge's pull-off of the law (Eq. 4 with K_Ic = 0) while keeping the
// materials, and keeps a registered contact law.
#include "dem/contact/contact_law_registry.h"
#include "dem/contact/particle_law.h"
#include "dem/die/jamming_study.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <variant>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

namespace
{
  DieRecord
  compaction_row(const int step, const double rho, const double Z, double p)
  {
    DieRecord r;
    r.stage                = "compaction";
    r.step                 = step;
    r.relative_density     = rho;
    r.coordination_number  = Z;
    r.upper_punch_pressure = p;
    return r;
  }
} // namespace

/// Rows of Eq. (14) above the pressure resolution among rows that a fit
/// must not see (the deposit, unjammed states with an arbitrary Z below the
/// resolution, an unloading branch): the fit returns the closed form's
/// parameters.
TEST(JammingStudy, FitUsesOnlyTheJammedCompactionStates)
{
  const double           Z_c = 4.2, Z_0 = 8.0, rho_c = 0.57, theta = 0.6;
  const double           resolution = 5e3;
  std::vector<DieRecord> rows{compaction_row(0, 0.48, 0.0, 0.0)};
  int                    step = 1;
  for (double rho = 0.50; rho < 0.57; rho += 0.01)
    rows.push_back(compaction_row(step++, rho, 1.0 + rho, 0.5 * resolution));
  for (int k = 0; k < 20; ++k)
    {
      const double rho = 0.58 + 0.01 * k;
      rows.push_back(compaction_row(step++,
                                    rho,
                                    Z_c + Z_0 * std::pow(rho - rho_c, theta),
                                    1e6 * (rho - rho_c)));
    }
  DieRecord unloading = compaction_row(1, 0.70, 1.0, 1e6);
  unloading.stage     = "unloading";
  rows.push_back(unloading);

  EXPECT_EQ(jammed_compaction(rows, resolution).size(), 20u);
  const auto fit = fit_jamming(rows, resolution);
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->Z_c, Z_c, 1e-3);
  EXPECT_NEAR(fit->rho_c, rho_c, 1e-4);
  EXPECT_NEAR(fit->theta, theta, 1e-3);

  // Fewer than five jammed states: no fit.
  rows.resize(12);
  EXPECT_FALSE(fit_jamming(rows, resolution).has_value());
}

/// The interior fit reads the interior's own columns (solid fraction,
/// -sigma_zz, Z) and skips rows without an interior (NaN): on a path whose
/// interior follows Eq. (14) with other parameters than the whole bed, each
/// region's fit returns its own closed form.
TEST(JammingStudy, InteriorFitReadsTheInteriorColumns)
{
  const double           resolution = 5e3;
  const double           Z_c = 4.2, Z_0 = 8.0, rho_c = 0.57, theta = 0.6;
  const double           Zi_c = 5.1, Zi_0 = 6.0, rhoi_c = 0.62, thetai = 0.45;
  std::vector<DieRecord> rows{compaction_row(0, 0.48, 0.0, 0.0)};
  rows.back().rho_interior = std::nan("");
  for (int k = 0; k < 20; ++k)
    {
      const double rho        = 0.58 + 0.01 * k;
      const double rhoi       = rho + 0.05;
      DieRecord    r          = compaction_row(k + 1,
                                   rho,
                                   Z_c + Z_0 * std::pow(rho - rho_c, theta),
                                   1e6 * (rho - rho_c));
      r.rho_interior          = rhoi;
      r.sigma_zz_interior     = -1e6 * (rhoi - rhoi_c);
      r.coordination_interior = Zi_c + Zi_0 * std::pow(rhoi - rhoi_c, thetai);
      if (k == 10) // a state whose interior holds no particle
        r.rho_interior = r.sigma_zz_interior = r.coordination_interior
          = std::nan("");
      rows.push_back(r);
    }
  const auto bed      = fit_jamming(rows, resolution);
  const auto interior = fit_jamming(rows, resolution, DieRegion::interior);
  ASSERT_TRUE(bed.has_value());
  ASSERT_TRUE(interior.has_value());
  EXPECT_NEAR(bed->rho_c, rho_c, 1e-4);
  EXPECT_NEAR(interior->Z_c, Zi_c, 1e-3);
  EXPECT_NEAR(interior->rho_c, rhoi_c, 1e-4);
  EXPECT_NEAR(interior->theta, thetai, 1e-3);
}

/// K_Ic = 0 leaves the materials and switches the bridges off: in the
/// unloading range of a bonded contact the bridge of the original law pulls
/// harder; on first loading both laws agree.
TEST(JammingStudy, ZeroToughnessKeepsMaterialsAndRemovesBridges)
{
  const ContactModel bonded   = material1::contact_model();
  const ContactModel unbonded = with_fracture_toughness(bonded, 0.0);
  ASSERT_EQ(unbonded.n_materials(), 1u);
  EXPECT_EQ(unbonded.fracture_toughness(0, 0), 0.0);
  EXPECT_EQ(unbonded.material(0).youngs_modulus,
            bonded.material(0).youngs_modulus);
  EXPECT_EQ(unbonded.regularization, bonded.regularization);

  // A contact plastically loaded to a_p = R / 10 and unloaded halfway to
  // its breakage overlap: the bridge pulls (K_Ic > 0) where the unbonded
  // contact does not pull harder; in compression beyond gamma_p, where a
  // > a_p, both laws are the same plastic loading curve.
  const double R   = material1::R;
  const auto   lb  = bonded_law(bonded.pair_law(0, R, 0, R));
  const auto   lu  = bonded_law(unbonded.pair_law(0, R, 0, R));
  const double a_p = R / 10, gamma_p = lb.plastic_overlap(a_p);
  const double gamma = 0.5 * (gamma_p + lb.breakage_overlap(a_p));
  EXPECT_LT(lb.response(gamma, a_p, a_p).force, 0.0);
  EXPECT_LT(lb.response(gamma, a_p, a_p).force,
            lu.response(gamma, a_p, a_p).force);
  EXPECT_DOUBLE_EQ(lb.response(1.5 * gamma_p, 0.0, 0.0).force,
                   lu.response(1.5 * gamma_p, 0.0, 0.0).force);

  std::ostringstream csv;
  JammingResult      r;
  r.study_case = {0.0, true};
  write_jamming_csv(csv, "m1", "bonded-elastoplastic", {r});
  EXPECT_EQ(csv.str(),
            "material,fracture_toughness,protocol,rho_c_Z,Z_c,theta,"
            "rho_jammed,Z_jammed,rho_c_Z_interior,Z_c_interior,"
            "theta_interior,contact_law\n"
            "m1,0,frozen-history,,,,0,0,,,,bonded-elastoplastic\n");
}

/// A model whose contacts follow a registered law keeps that law when its
/// toughness is replaced (the jamming study of `compax jamming` with a
/// Contact law other than the bonded one): every pair then holds the
/// registered law, whose force at an overlap is that law's, not the bonded
/// law's.
TEST(JammingStudy, ZeroToughnessKeepsARegisteredLaw)
{
  ContactModel                registered = material1::contact_model();
  const RegisteredContactLaw *entry = find_contact_law("plastic-hardening");
  ASSERT_NE(entry, nullptr);
  registered.use_registered_law(*entry,
                                {{"Plastic stiffness", 150e6},
                                 {"Plastic exponent", 2.0}});
  const ContactModel unbonded = with_fracture_toughness(registered, 0.0);
  EXPECT_EQ(unbonded.registered_law(), entry);
  EXPECT_EQ(unbonded.fracture_toughness(0, 0), 0.0);

  const double R    = material1::R;
  const auto   law  = unbonded.pair_law(0, R, 0, R);
  const auto  *held = std::get_if<PlasticHardeningLaw>(&law);
  ASSERT_NE(held, nullptr);
  // Unloaded from a plastic radius of R/10, the plastic-hardening law
  // retraces its loading curve where the bonded law unloads elastically.
  const auto bonded
    = bonded_law(material1::contact_model().pair_law(0, R, 0, R));
  const double a_p   = R / 10;
  const double gamma = 0.9 * bonded.plastic_overlap(a_p);
  EXPECT_EQ(law_response(law, gamma, bonded.history(a_p, 0.0)).force,
            held->response(gamma).force);
  EXPECT_GT(held->response(gamma).force,
            bonded.response(gamma, a_p, 0.0).force);
}

#include "fem/material_registry.h"
#include "input/input_error.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <vector>

using namespace compax;

namespace
{
  /// The subsection Material as the tablet declares it from a registry,
  /// with @p text (a .prm body) parsed into it.
  void
  declare_and_parse(dealii::ParameterHandler    &prm,
                    const fem::MaterialRegistry &materials,
                    const std::string           &text)
  {
    prm.enter_subsection("Material");
    materials.declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Material\n" + text + "end\n");
  }

  /// Stress of a fresh material point after the uniaxial strain increment
  /// eps_zz = @p eps (no lateral strain) [Pa].
  dealii::SymmetricTensor<2, 3>
  uniaxial_strain_stress(const fem::MaterialModel &m, const double eps)
  {
    std::vector<double> old_h(m.n_history()), new_h(m.n_history());
    m.initialize(0.6, dealii::make_array_view(old_h));
    fem::MaterialIncrement inc;
    inc.strain_increment[2][2] = eps;
    inc.deformation_increment[2][2] += eps;
    fem::MaterialResponse r;
    EXPECT_TRUE(m.evaluate(inc,
                           dealii::make_array_view(std::as_const(old_h)),
                           dealii::make_array_view(new_h),
                           r));
    return r.stress;
  }
} // namespace

TEST(MaterialRegistry, LinearElasticReadsItsOwnEntriesIntoTheClosedForm)
{
  const fem::MaterialRegistry materials = fem::closed_form_materials();
  dealii::ParameterHandler    prm;
  declare_and_parse(prm,
                    materials,
                    "set Young's modulus = 7e9\nset Poisson's ratio = 0.2\n");
  prm.enter_subsection("Material");
  const auto material = materials.find("linear-elastic").create(prm);
  prm.leave_subsection();
  // Uniaxial strain: sigma_zz = E (1 - nu) / ((1 + nu)(1 - 2 nu)) eps,
  // sigma_rr = nu / (1 - nu) sigma_zz.
  const double E = 7e9, nu = 0.2, eps = -1e-4;
  const auto   s  = uniaxial_strain_stress(*material, eps);
  const double zz = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)) * eps;
  EXPECT_NEAR(s[2][2], zz, 1e-12 * std::abs(zz));
  EXPECT_NEAR(s[0][0], nu / (1.0 - nu) * zz, 1e-12 * std::abs(zz));
  EXPECT_EQ(material->name(), "linear-elastic");
}

TEST(MaterialRegistry, AnUnreadableDpcTableIsBadInputNamingTheEntry)
{
  const fem::MaterialRegistry materials = fem::closed_form_materials();
  dealii::ParameterHandler    prm;
  declare_and_parse(prm, materials, "set DPC table = /no/such/table.csv\n");
  prm.enter_subsection("Material");
  try
    {
      materials.find("drucker-prager-cap").create(prm);
      FAIL() << "a missing DPC table was accepted";
    }
  catch (const input::InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Material/DPC table"),
                std::string::npos)
        << e.what();
    }
}

TEST(MaterialRegistry, AMaterialJoinsWithItsOwnEntriesByOneRegistration)
{
  fem::MaterialRegistry materials = fem::closed_form_materials();
  // A user's material: linear elasticity with a fixed Poisson's ratio and
  // its own modulus entry.
  materials.add(
    {"stiff-elastic",
     "a user's material",
     [](dealii::ParameterHandler &prm) {
       prm.declare_entry("Stiff modulus",
                         "1e10",
                         dealii::Patterns::Double(0.0));
     },
     [](dealii::ParameterHandler &prm)
       -> std::shared_ptr<const fem::MaterialModel> {
       return fem::closed_form_materials().find("linear-elastic").create(prm);
     }});
  EXPECT_EQ(materials.selection(),
            "drucker-prager-cap|linear-elastic|stiff-elastic");
  EXPECT_NE(materials.documentation().find("stiff-elastic: a user's"),
            std::string::npos);
  dealii::ParameterHandler prm;
  declare_and_parse(prm, materials, "set Stiff modulus = 3e10\n");
  prm.enter_subsection("Material");
  EXPECT_DOUBLE_EQ(prm.get_double("Stiff modulus"), 3e10);
  prm.leave_subsection();
  EXPECT_THROW(materials.add({"linear-elastic", "again", {}, {}}),
               std::logic_error);
  EXPECT_THROW(materials.find("granite"), std::out_of_range);
}

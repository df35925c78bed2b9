// `compax die` with elastic frictionless spheres and the nonlocal contact
// formulation (Gonzalez & Cuitino 2012) through the real executable on a
// tiny bed: it runs, every converged state balances the punch forces (a
// frictionless die carries no axial load), the nonlocal terms change the
// forces of the Hertz run on the same packing, and the nonlocal
// formulation with the bonded elasto-plastic law is refused.

#include "app_test_support.h"

#include <cmath>

using compax::testing::AppTest;
using compax::testing::contact_subsection;
using compax::testing::Csv;
using compax::testing::expect_balanced_punches;
using compax::testing::last_in_stage;

namespace
{
  std::string
  tiny_bed(const std::string &law, const std::string &formulation)
  {
    return "subsection Packing\n"
           " set Number of particles = 40\n"
           " set Die diameter = 2e-3\n"
           "end\n"
           "subsection Protocol\n"
           " set Final relative density = 0.62\n"
           " set Compaction steps = 5\n"
           " set Unloading points = 0.62\n"
           "end\n"
           + contact_subsection(law, formulation);
  }

  double
  final_punch_force(const Csv &die)
  {
    return last_in_stage(die, "compaction", "upper_punch_force");
  }
} // namespace

class DieNonlocal : public AppTest
{
};

TEST_F(DieNonlocal, TinyBedCompactsWithBalancedPunchForces)
{
  write("nonlocal.prm", tiny_bed("elastic", "nonlocal"));
  const auto r = compax("die nonlocal.prm -o nl");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("nonlocal contact formulation"), std::string::npos);
  const Csv die(folder / "nl" / "die.csv");
  expect_balanced_punches(die);
  bool unloading = false;
  for (std::size_t i = 0; i < die.rows(); ++i)
    {
      EXPECT_EQ(die.column.at("bonds")[i], 0.0);
      unloading |= die.text.at("stage")[i] == "unloading";
    }
  EXPECT_TRUE(unloading);

  // Hertz on the same packing: same consolidation (Hertz in both), other
  // forces once the nonlocal terms act.
  write("hertz.prm", tiny_bed("elastic", "hertz"));
  const auto h = compax("die hertz.prm -o hz");
  ASSERT_EQ(h.exit_code, 0) << h.err << h.out;
  const Csv    hz(folder / "hz" / "die.csv");
  const double f_nl = final_punch_force(die), f_hz = final_punch_force(hz);
  ASSERT_GT(f_hz, 0.0);
  EXPECT_GT(std::abs(f_nl - f_hz), 1e-3 * f_hz);
}

TEST_F(DieNonlocal, NonlocalWithBondedLawIsRefused)
{
  write("bad.prm", tiny_bed("bonded-elastoplastic", "nonlocal"));
  const auto r = compax("die bad.prm -o bad");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("Contact/Formulation"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nonlocal"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Contact law = elastic"), std::string::npos) << r.err;
}

// `compax die` with elastic frictionless spheres and the nonlocal contact
// formulation (Gonzalez & Cuitino 2012) through the real executable on a
// tiny bed: it runs, every converged state balances the punch forces (a
// frictionless die carries no axial load), the nonlocal terms change the
// forces of the Hertz run on the same packing, and the nonlocal
// formulation with the bonded elasto-plastic law is refused.

#include "nonlocal_app_test.h"

using namespace compax::testing;

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
} // namespace

using DieNonlocal = NonlocalAppTest;

TEST_F(DieNonlocal, TinyBedCompactsWithBalancedPunchForces)
{
  // Hertz on the same packing: same consolidation (Hertz in both), other
  // forces once the nonlocal terms act.
  ASSERT_NO_FATAL_FAILURE(expect_nonlocal_changes_hertz(
    "die", tiny_bed, "die.csv", "compaction", "upper_punch_force"));
  const Csv die(folder / "nl" / "die.csv");
  expect_balanced_punches(die);
  bool unloading = false;
  for (std::size_t i = 0; i < die.rows(); ++i)
    {
      EXPECT_EQ(die.column.at("bonds")[i], 0.0);
      unloading |= die.text.at("stage")[i] == "unloading";
    }
  EXPECT_TRUE(unloading);
}

TEST_F(DieNonlocal, NonlocalWithBondedLawIsRefused)
{
  const auto r = expect_bonded_nonlocal_refused("die", tiny_bed);
  EXPECT_NE(r.err.find("nonlocal"), std::string::npos) << r.err;
}

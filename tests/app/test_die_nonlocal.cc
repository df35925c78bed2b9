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

// The nonlocal formulation is a layer on any elastic law: on the registry's
// Hertz law it follows the built-in elastic (Hertz) run, row by row, to
// the solver's tolerance (the two differ only in the rounding of the wall
// contacts' effective radius, R against 1/(1/R + 1/inf)).
TEST_F(DieNonlocal, LayerOnTheRegisteredHertzLawFollowsTheElasticRun)
{
  write("elastic.prm", tiny_bed("elastic", "nonlocal"));
  const auto e = compax("die elastic.prm -o elastic");
  ASSERT_EQ(e.exit_code, 0) << e.err << e.out;
  write("registered.prm", tiny_bed("hertz", "nonlocal"));
  const auto r = compax("die registered.prm -o registered");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("nonlocal contact formulation"), std::string::npos);

  const Csv elastic(folder / "elastic" / "die.csv");
  const Csv registered(folder / "registered" / "die.csv");
  ASSERT_EQ(registered.rows(), elastic.rows());
  const auto &P       = elastic.column.at("upper_punch_force");
  double      largest = 0.0;
  for (const double p : P)
    largest = std::max(largest, std::abs(p));
  ASSERT_GT(largest, 0.0);
  for (std::size_t i = 0; i < elastic.rows(); ++i)
    {
      EXPECT_NEAR(registered.column.at("relative_density")[i],
                  elastic.column.at("relative_density")[i],
                  1e-9);
      EXPECT_NEAR(registered.column.at("upper_punch_force")[i],
                  P[i],
                  1e-6 * largest)
        << "row " << i;
    }
}

/// The nonlocal far field is that of elastic spheres: a law that keeps
/// internal variables (walton-braun) or whose bodies are plastic
/// (plastic-hardening, history-free) is refused by name.
TEST_F(DieNonlocal, NonlocalOnALawWithoutElasticBodiesIsRefused)
{
  for (const std::string law : {"walton-braun", "plastic-hardening"})
    {
      write("bad.prm", tiny_bed(law, "nonlocal"));
      const auto r = compax("die bad.prm -o bad");
      EXPECT_EQ(r.exit_code, 2) << law;
      EXPECT_NE(r.err.find("Contact/Formulation"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(law), std::string::npos) << r.err;
      EXPECT_FALSE(std::filesystem::exists(folder / "bad" / "die.csv"));
    }
}

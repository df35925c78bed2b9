// `compax rve` with elastic frictionless spheres and the nonlocal contact
// formulation (Gonzalez & Cuitino 2012) through the real executable on a
// small cell: it runs, the cell follows the uniaxial path exactly (mass
// conservation rho exp(eps_zz) = rho_0), jammed states are in equilibrium,
// it unloads to zero axial stress, the nonlocal terms change the stress of
// the Hertz run on the same packing, and the nonlocal formulation with the
// bonded elasto-plastic law is refused.

#include "nonlocal_app_test.h"

#include <cmath>

using namespace compax::testing;

namespace
{
  std::string
  small_cell(const std::string &law, const std::string &formulation)
  {
    return "subsection Packing\n"
           " set Number of particles = 40\n"
           " set Seed = 4\n"
           "end\n"
           "subsection Strain path\n"
           " set Target relative density = 0.72\n"
           " set Loading steps = 8\n"
           " set Unloading strain step = 3e-3\n"
           "end\n"
           "subsection Output\n"
           " set Snapshot interval = 0\n"
           "end\n"
           + contact_subsection(law, formulation);
  }
} // namespace

using RveNonlocal = NonlocalAppTest;

TEST_F(RveNonlocal, SmallCellLoadsAndUnloads)
{
  // The nonlocal terms change the stress of the Hertz run.
  ASSERT_NO_FATAL_FAILURE(expect_nonlocal_changes_hertz(
    "rve", small_cell, "rve.csv", "loading", "mean_pressure"));
  const Csv rve(folder / "nl" / "rve.csv");
  ASSERT_GT(rve.rows(), 10u);
  const double rho0   = rve.column.at("relative_density")[0];
  bool         jammed = false, unloading = false;
  for (std::size_t i = 0; i < rve.rows(); ++i)
    {
      EXPECT_NEAR(rve.column.at("relative_density")[i]
                    * std::exp(rve.column.at("eps_zz")[i]),
                  rho0,
                  1e-9 * rho0)
        << "row " << i;
      if (rve.column.at("jammed")[i] == 1.0)
        {
          jammed = true;
          EXPECT_LE(rve.column.at("residual")[i], 1e-6) << "row " << i;
          EXPECT_LT(rve.column.at("sigma_zz")[i], 0.0) << "row " << i;
        }
      unloading |= rve.text.at("stage")[i] == "unloading";
    }
  EXPECT_TRUE(jammed);
  EXPECT_TRUE(unloading);
  // Unloaded: the axial stress is gone (to the relaxation's resolution,
  // 1 % of the 0.5 MPa jamming pressure), far below its peak.
  EXPECT_GE(rve.column.at("sigma_zz").back(), -0.01 * 0.5e6);
  EXPECT_GT(last_in_stage(rve, "loading", "mean_pressure"), 1e6);
}

TEST_F(RveNonlocal, NonlocalWithBondedLawIsRefused)
{
  expect_bonded_nonlocal_refused("rve", small_cell);
}

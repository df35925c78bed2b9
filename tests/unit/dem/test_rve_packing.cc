/// The starting packings of an RVE: compressed gas or deposit compacted
/// on the bonded path (make_rve_packing()).
#include "dem/rve/homogenization.h"
#include "dem/rve/rve_packing.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax::dem;
namespace material1 = compax::testing::material1;
using material1::R;

namespace
{
  PeriodicPackingSpec
  spec(const PackingProtocol protocol, const double rho)
  {
    PeriodicPackingSpec s;
    s.particle_count      = 120;
    s.sizes.median_radius = R;
    s.relative_density    = rho;
    s.seed                = 5;
    s.protocol            = protocol;
    return s;
  }
} // namespace

/// The deposited protocol compacts the deposit by uniaxial strain along z
/// to exactly the density asked for (mass conservation: the lateral edges
/// keep their length, the axial one shrinks by rho_dep / rho), makes that
/// state the reference, and commits histories on the way (bonded path):
/// with relaxed loose states the chains they leave grow plastic radii; with
/// balanced ones (the default) the cell below jamming carries no resolved
/// force, and no contact has deformed plastically.
TEST(RvePacking, DepositCompactedUniaxiallyToTheDensityAskedFor)
{
  const ContactModel model = material1::contact_model();
  const PeriodicBed  deposit
    = make_rve_deposit(spec(PackingProtocol::deposited, 0.0));
  const double      rho_dep = deposit.relative_density();
  const double      rho     = rho_dep + 0.04;
  const PeriodicBed bed
    = make_rve_packing(spec(PackingProtocol::deposited, rho), model);
  EXPECT_NEAR(bed.relative_density(), rho, 1e-12);
  EXPECT_TRUE(bed.deformation.isIdentity());
  EXPECT_EQ(bed.reference_lattice, bed.cell.lattice());
  const Eigen::Matrix3d H0 = deposit.cell.lattice(), H = bed.cell.lattice();
  EXPECT_NEAR(H(0, 0), H0(0, 0), 1e-15);
  EXPECT_NEAR(H(1, 1), H0(1, 1), 1e-15);
  EXPECT_NEAR(H(2, 2), H0(2, 2) * rho_dep / rho, 1e-12 * H0(2, 2));
  // Along x: the deposit's height becomes the x edge, and shrinks.
  const PeriodicBed along_x
    = make_rve_packing(spec(PackingProtocol::deposited, rho), model, {}, 0);
  EXPECT_NEAR(along_x.relative_density(), rho, 1e-12);
  EXPECT_NEAR(along_x.cell.lattice()(0, 0),
              H0(2, 2) * rho_dep / rho,
              1e-12 * H0(2, 2));
  EXPECT_NEAR(along_x.cell.lattice()(2, 2), H0(0, 0), 1e-15);
  const auto plastic_contacts = [](const PeriodicBed &b) {
    int n = 0;
    for (const PeriodicContact &c : b.contacts.pairs)
      n += BondedElastoplasticLaw::a_p(c.history) > 0.0;
    return n;
  };
  const RveLoadingOptions balanced;
  EXPECT_EQ(plastic_contacts(bed), 0);
  EXPECT_LT(std::abs(mean_pressure(bed)),
            balanced.force_floor_fraction * balanced.jamming_pressure);
  RveLoadingOptions relaxed;
  relaxed.unjammed_equilibrium = UnjammedEquilibrium::relaxation;
  const PeriodicBed relaxed_bed
    = make_rve_packing(spec(PackingProtocol::deposited, rho), model, relaxed);
  EXPECT_GT(plastic_contacts(relaxed_bed), 0);
  // Below jamming: the cell carries less than the jamming pressure.
  EXPECT_LT(mean_pressure(relaxed_bed), relaxed.jamming_pressure);
}

/// A density below the deposit's is rejected (naming both) or, if asked,
/// the deposit is returned as it is; the gas protocol is
/// make_periodic_packing().
TEST(RvePacking, DenserDepositRejectedOrKeptGasUnchanged)
{
  const ContactModel model = material1::contact_model();
  const double rho_dep = make_rve_deposit(spec(PackingProtocol::deposited, 0.0))
                           .relative_density();
  try
    {
      make_rve_packing(spec(PackingProtocol::deposited, rho_dep - 0.05), model);
      FAIL() << "no DepositDensityError";
    }
  catch (const DepositDensityError &e)
    {
      EXPECT_DOUBLE_EQ(e.deposit_density, rho_dep);
      EXPECT_DOUBLE_EQ(e.requested_density, rho_dep - 0.05);
    }
  const PeriodicBed kept
    = make_rve_packing(spec(PackingProtocol::deposited, rho_dep - 0.05),
                       model,
                       {},
                       2,
                       DenserDeposit::keep);
  EXPECT_DOUBLE_EQ(kept.relative_density(), rho_dep);

  const PeriodicBed gas
    = make_rve_packing(spec(PackingProtocol::compressed_gas, 0.55), model);
  const PeriodicBed direct
    = make_periodic_packing(spec(PackingProtocol::compressed_gas, 0.55), model);
  EXPECT_EQ(gas.particles.positions, direct.particles.positions);
  EXPECT_NEAR(gas.relative_density(), 0.55, 1e-9);
}

#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compax::dem;
namespace material1 = compax::testing::material1;
using material1::R;

namespace
{
  PeriodicPackingSpec
  small_spec()
  {
    PeriodicPackingSpec spec;
    spec.particle_count      = 80;
    spec.sizes.median_radius = R;
    spec.relative_density    = 0.55;
    spec.seed                = 3;
    return spec;
  }
} // namespace

/// The packing reaches its density, is virgin and free of overlaps at a
/// density below jamming, and is reproducible.
TEST(RveLoading, PackingIsLooseVirginAndReproducible)
{
  const ContactModel model = material1::contact_model();
  const PeriodicBed  a     = make_periodic_packing(small_spec(), model);
  const PeriodicBed  b     = make_periodic_packing(small_spec(), model);
  EXPECT_NEAR(a.relative_density(), 0.55, 1e-9);
  EXPECT_TRUE(a.deformation.isIdentity());
  for (std::size_t i = 0; i < a.particles.size(); ++i)
    EXPECT_EQ(a.particles.positions[i], b.particles.positions[i]);
  double worst_overlap = 0.0;
  for (const PeriodicContact &c : a.contacts.pairs)
    {
      EXPECT_EQ(BondedElastoplasticLaw::a_p(c.history), 0.0);
      worst_overlap
        = std::max(worst_overlap,
                   2 * R - branch_vector(a.particles, a.cell, c).norm());
    }
  // Relaxed below jamming: overlaps are round-off of the relaxation.
  EXPECT_LT(worst_overlap, 1e-3 * R);
}

/// Uniaxial strain: the cell shape follows F exactly (mass conservation
/// rho F_zz = rho_0), the bed jams, the lateral stresses are compressive,
/// and every converged state is in equilibrium.
TEST(RveLoading, UniaxialStrainCompactsAndJams)
{
  const ContactModel model = material1::contact_model();
  PeriodicBed        bed   = make_periodic_packing(small_spec(), model);
  const double       rho0  = bed.relative_density();
  RveLoading         loading(model);
  Eigen::Matrix3d    step = Eigen::Matrix3d::Zero();
  step(2, 2)              = -0.01;
  bool jammed             = false;
  while (bed.relative_density() < 0.78)
    {
      const RveStepResult r = loading.apply_strain(bed, step);
      ASSERT_TRUE(r.converged);
      jammed = jammed || r.jammed;
    }
  EXPECT_TRUE(jammed);
  EXPECT_NEAR(bed.relative_density() * bed.deformation(2, 2), rho0, 1e-12);
  EXPECT_NEAR(bed.deformation(0, 0), 1.0, 1e-15);
  const Eigen::Matrix3d eps = logarithmic_strain(bed.deformation);
  EXPECT_NEAR(eps(2, 2), std::log(rho0 / bed.relative_density()), 1e-12);

  const Eigen::Matrix3d sigma = love_weber_stress(bed);
  EXPECT_LT(sigma(2, 2), 0.0);
  EXPECT_LT(sigma(0, 0), 0.0);
  EXPECT_LT(sigma(1, 1), 0.0);
  // Axial stress larger than lateral in die-like compaction.
  EXPECT_LT(sigma(2, 2), sigma(0, 0));

  // Equilibrium of the final state: every particle's net force small.
  PeriodicAssembler assembler;
  Eigen::VectorXd   F;
  const ContactSums sums = assembler.residual(bed, model, F);
  EXPECT_LT(max_particle_norm(F),
            loading.options().equilibrium.force_tolerance * sums.mean_force
              * 1.0000001);
}

/// The die's least-squares loose path (Algorithm 1 as printed) is not
/// offered for the periodic cell: the loading refuses it by name.
TEST(RveLoading, RefusesTheDiesLeastSquaresLoosePath)
{
  const ContactModel model = material1::contact_model();
  RveLoadingOptions  options;
  options.unjammed_equilibrium = UnjammedEquilibrium::least_squares;
  try
    {
      RveLoading loading(model, options);
      ADD_FAILURE() << "least-squares accepted";
    }
  catch (const std::invalid_argument &e)
    {
      EXPECT_NE(std::string(e.what()).find("least-squares"), std::string::npos);
    }
}

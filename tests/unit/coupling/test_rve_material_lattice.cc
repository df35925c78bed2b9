// An FE2 run of the tablet model whose RVEs are a simple cubic lattice,
// against the lattice's own mechanics: in a frictionless die every material
// point is in uniaxial strain, a Bravais lattice deforms affinely, and the
// Love-Weber stress of the lattice is the pair force over the face area,
// sigma_zz = -P(gamma_z) / a^2 and sigma_rr = -P(gamma_r) / (a a_z), with
// the pair law evaluated by hand along its own Eq. (13) history.
#include "coupling/rve_material.h"
#include "dem/contact/bonded_elastoplastic.h"
#include "fe2_test_support.h"
#include "fem/tablet_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace compax;

namespace
{
  constexpr double R = 100e-6;

  namespace material1 = compax::testing::material1;

  double
  mean_coordinate(const std::vector<dealii::Point<2>> &points,
                  const unsigned int                   axis)
  {
    double sum = 0.0;
    for (const auto &p : points)
      sum += p[axis];
    return sum / points.size();
  }

} // namespace

TEST(RveMaterialLattice, Fe2TabletOfSimpleCubicLatticeFollowsThePairLaw)
{
  const dem::ContactModel   model  = material1::contact_model();
  const double              gamma0 = 0.01 * R, a = 2 * R - gamma0;
  coupling::RveMaterialSpec spec;
  spec.pool            = {compax::testing::simple_cubic_cell(a, R, model)};
  spec.compaction_axis = 1; // the axial row of the r-z model
  // A lattice's stress is smooth: the continuum Newton balances it to its
  // own tolerance (the default resolution is that of random packings).
  spec.stress_resolution                   = 0.0;
  spec.tangent_floor_modulus               = 1e3;
  spec.loading.equilibrium.force_tolerance = 1e-10;
  const double rho_lattice = 4.0 / 3.0 * M_PI * R * R * R / (a * a * a);
  ASSERT_NEAR(spec.pool[0].relative_density(), rho_lattice, 1e-14);

  fem::TabletSolverSettings s;
  s.geometry.die_diameter    = 10e-3;
  s.geometry.fill_height     = 5e-3;
  s.geometry.n_radial_cells  = 1;
  s.wall_friction            = 0.0;
  s.initial_relative_density = spec.pool[0].relative_density();
  s.penalty_factor           = 1e7;
  s.tolerance                = 1e-10;
  auto material = std::make_shared<coupling::RveMaterial>(spec, model);
  fem::TabletSolver<2> solver(s, material, MPI_COMM_WORLD);

  const dem::BondedElastoplasticLaw law
    = dem::bonded_law(model.pair_law(0, R, 0, R));
  // Histories of the axial and radial contacts, updated by Eq. (13) after
  // each converged step as the RVE does.
  dem::ContactHistory axial, radial;
  const double        H = s.geometry.fill_height;
  const double        D = s.geometry.die_diameter;
  // Compaction by 0.6 % in six steps, then elastic unloading by 0.02 %.
  // Every point jams at once (the lattice density is its jamming density),
  // so the floor carries no stress (it is released at jamming, the
  // default) and only stiffens the tangent.
  const double strokes[] = {1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3, 5.9e-3, 5.8e-3};
  for (const double stroke : strokes)
    {
      const double new_height = H * (1.0 - stroke);
      ASSERT_TRUE(solver.advance(new_height, 0.0)) << "stroke " << stroke;

      // The lattice spacings follow the compact's actual surfaces: the
      // penalty contacts let the punch and the wall in by ~1e-7 of the
      // strain, which the stiff unloading branch would feel.
      const double a_z
        = a * mean_coordinate(solver.boundary_positions(3), 1) / H;
      const double a_r
        = a * mean_coordinate(solver.boundary_positions(1), 0) / (0.5 * D);
      const double gamma_z = 2 * R - a_z, gamma_r = 2 * R - a_r;
      const auto   axial_response = law.evaluate(gamma_z, axial);
      const double P_z            = axial_response.force;
      const double P_r            = law.evaluate(gamma_r, radial).force;
      axial                       = law.updated_history(gamma_z, axial);
      radial                      = law.updated_history(gamma_r, radial);

      const double sigma_zz = -P_z / (a_r * a_r);
      const double sigma_rr = -P_r / (a_r * a_z);
      // Tolerance: 1e-6, plus what an axial strain error of 1e-9 (the
      // continuum Newton's tolerance level) makes of the stress on the
      // contact's current branch (the elastic unloading branch of a bonded
      // contact is far stiffer than plastic loading).
      const double tolerance
        = 1e-6 + axial_response.stiffness * a_z * 1e-9 / std::abs(P_z);
      const auto  &f = solver.forces();
      const double A = solver.punch_area();
      EXPECT_NEAR(f.upper_punch_force / A / -sigma_zz, 1.0, tolerance)
        << "stroke " << stroke;
      EXPECT_NEAR(f.lower_punch_force / A / -sigma_zz, 1.0, tolerance);
      EXPECT_NEAR(f.die_wall_normal_force / f.die_wall_contact_area / -sigma_rr,
                  1.0,
                  1e-6)
        << "stroke " << stroke;
    }
  // The last steps unloaded: the axial contacts are on the elastic branch,
  // inside their plastic radius.
  EXPECT_LT(law.contact_radius(2 * R - a * (1.0 - 5.8e-3),
                               dem::BondedElastoplasticLaw::a_p(axial)),
            0.999 * dem::BondedElastoplasticLaw::a_p(axial));
}

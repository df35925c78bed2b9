#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_bed_system.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/narrow_polydisperse_cell.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

using namespace compax::dem;
namespace material1 = compax::testing::material1;
using material1::R;

namespace
{
  /// n^3 copies of a cubic motif of edge a (fractional positions).
  PeriodicBed
  cubic_lattice(const std::vector<Eigen::Vector3d> &motif,
                const double                        a,
                const int                           n,
                const ContactModel                 &model)
  {
    PeriodicBed bed;
    bed.cell
      = PeriodicCell::box(Eigen::Vector3d::Constant(n * a), {true, true, true});
    bed.reference_lattice = bed.cell.lattice();
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k)
          for (const Eigen::Vector3d &s : motif)
            bed.particles.add(a * (Eigen::Vector3d(i, j, k) + s), R);
    bed.contacts.set_skin(0.3 * R);
    bed.contacts.rebuild(bed.particles, bed.cell, model);
    return bed;
  }

  double
  relative_difference(const Matrix6d &a, const Matrix6d &b)
  {
    return (a - b).norm() / b.norm();
  }

  /// Equilibrium of a cell at its current lattice, histories frozen.
  EquilibriumResult
  equilibrate_frozen(PeriodicBed        &bed,
                     const ContactModel &model,
                     const double        tolerance)
  {
    EquilibriumOptions options;
    options.force_tolerance = tolerance;
    options.step_tolerance  = tolerance;
    PeriodicAssembler assembler;
    PeriodicBedSystem system(bed, model, assembler);
    TrustRegionNewton newton(options);
    return newton.solve(system);
  }

  /**
   * A disordered cell compacted in uniaxial strain into the jammed range,
   * then strained by one more trial increment equilibrated with frozen
   * histories, as a multiscale Newton iteration does: loading contacts
   * are strictly on the plastic branch and unloading ones strictly on
   * the elastic branch, none on the kink between them (a converged step's
   * history update puts every loading contact exactly there).
   *
   * The central difference is a reference only where no contact changes
   * branch within the difference step. The loose regime is balanced by
   * FIRE here: the L-BFGS path (the default) ends, at the unloading trial,
   * with a contact within about 1e-6 of strain of such a change (the
   * difference to the condensed tangent then falls from 2.9e-3 at a step
   * of 4e-6 to 7.9e-4 at 2.5e-7, in the yy column only).
   */
  PeriodicBed
  trial_state(const ContactModel &model, const Eigen::Matrix3d &trial_strain)
  {
    PeriodicBed bed = make_periodic_packing(
      compax::testing::narrow_polydisperse_cell(60, R, 1.2, 0.60, 7), model);
    RveLoadingOptions fire;
    fire.unjammed_equilibrium = UnjammedEquilibrium::balanced_relaxation;
    RveLoading      loading(model, fire);
    Eigen::Matrix3d compress = Eigen::Matrix3d::Zero();
    compress(2, 2)           = -0.01;
    while (bed.relative_density() < 0.74)
      EXPECT_TRUE(loading.apply_strain(bed, compress).converged);
    map_affinely(bed,
                 (Eigen::Matrix3d::Identity() + trial_strain)
                   * bed.deformation);
    EXPECT_TRUE(equilibrate_frozen(bed, model, 1e-10).converged);
    return bed;
  }

  Eigen::Matrix3d
  uniaxial(const double eps_zz)
  {
    Eigen::Matrix3d e = Eigen::Matrix3d::Zero();
    e(2, 2)           = eps_zz;
    return e;
  }
} // namespace

/// Simple cubic lattice with overlap gamma on every face contact:
/// sigma = -P(gamma) / a^2 I, a = 2R - gamma (Love-Weber by hand).
TEST(RveHomogenization, LoveWeberStressOfSimpleCubicLattice)
{
  const ContactModel model = material1::contact_model();
  const double       gamma = 0.02 * R, a = 2 * R - gamma;
  const PeriodicBed bed = cubic_lattice({Eigen::Vector3d::Zero()}, a, 2, model);
  ASSERT_EQ(bed.contacts.pairs.size(), 8u * 6u / 2u + 0u);
  const double P
    = bonded_law(model.pair_law(0, R, 0, R)).response(gamma, 0.0, 0.0).force;
  const Eigen::Matrix3d sigma = love_weber_stress(bed);
  EXPECT_NEAR(sigma(0, 0), -P / (a * a), 1e-12 * P / (a * a));
  EXPECT_NEAR(sigma(1, 1), -P / (a * a), 1e-12 * P / (a * a));
  EXPECT_NEAR(sigma(2, 2), -P / (a * a), 1e-12 * P / (a * a));
  EXPECT_NEAR(sigma(0, 1), 0.0, 1e-12 * P / (a * a));
  EXPECT_NEAR(sigma(1, 2), 0.0, 1e-12 * P / (a * a));
}

/// FCC (conventional cell of edge a_c, nearest distance l = a_c / sqrt 2):
/// twelve contacts per particle with sum n n^T = 4 I, so
/// sigma = -(N/V) (1/2) P l 4 / 3 ... = -2 P l (N/V) / 3 * 3 ... written
/// out: sigma = -(1/V) sum_c P l n n^T = -(N/V) 6 P l (4/12) I.
TEST(RveHomogenization, LoveWeberStressOfFaceCentredCubicLattice)
{
  const ContactModel model = material1::contact_model();
  const double       gamma = 0.03 * R, l = 2 * R - gamma;
  const double       a_c = std::sqrt(2.0) * l;
  const PeriodicBed  bed = cubic_lattice({Eigen::Vector3d(0, 0, 0),
                                          Eigen::Vector3d(0.5, 0.5, 0),
                                          Eigen::Vector3d(0.5, 0, 0.5),
                                          Eigen::Vector3d(0, 0.5, 0.5)},
                                        a_c,
                                        1,
                                        model);
  const double       P
    = bonded_law(model.pair_law(0, R, 0, R)).response(gamma, 0.0, 0.0).force;
  const double          N_over_V = 4.0 / (a_c * a_c * a_c);
  const double          expected = -N_over_V * 6.0 * P * l * (4.0 / 12.0);
  const Eigen::Matrix3d sigma    = love_weber_stress(bed);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(sigma(d, d), expected, 1e-12 * std::abs(expected));
  EXPECT_NEAR(sigma(0, 2), 0.0, 1e-12 * std::abs(expected));
}

/// K of the periodic assembler is the central difference of its residual,
/// with pairs touching through several images.
TEST(RveHomogenization, PeriodicStiffnessEqualsDifferenceOfResidual)
{
  const ContactModel model = material1::contact_model();
  PeriodicBed        bed
    = cubic_lattice({Eigen::Vector3d::Zero(), Eigen::Vector3d(0.5, 0.5, 0.5)},
                    2 * R * 1.1,
                    2,
                    model);
  // Shear the cell so that the lattice is skewed, and jiggle the particles.
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 1)           = 0.05;
  F(2, 2)           = 0.90;
  map_affinely(bed, F);
  for (std::size_t i = 0; i < bed.particles.size(); ++i)
    bed.particles.positions[i] += 0.01 * R
                                  * Eigen::Vector3d(std::sin(3.0 * i),
                                                    std::cos(5.0 * i),
                                                    std::sin(7.0 * i));
  PeriodicAssembler assembler;
  Eigen::VectorXd   F0, Fp, Fm;
  BlockSparseMatrix K;
  assembler.assemble(bed, model, F0, K);
  ASSERT_GT(bed.contacts.pairs.size(), 20u);
  const Eigen::MatrixXd Kd    = Eigen::MatrixXd(K.to_sparse());
  const double          h     = 1e-7 * R;
  double                worst = 0.0;
  for (Eigen::Index col = 0; col < Kd.cols(); ++col)
    {
      auto x = bed.particles.coordinates();
      x[col] += h;
      assembler.residual(bed, model, Fp);
      x[col] -= 2 * h;
      assembler.residual(bed, model, Fm);
      x[col] += h;
      const Eigen::VectorXd fd = (Fp - Fm) / (2 * h);
      worst = std::max(worst, (fd - Kd.col(col)).norm() / Kd.norm());
    }
  EXPECT_LT(worst, 1e-6);
}

/// For a Bravais lattice every particle is a centre of symmetry: the affine
/// motion is an equilibrium, so the condensed tangent equals the affine one.
TEST(RveHomogenization, CondensedEqualsAffineForSimpleCubicLattice)
{
  const ContactModel model = material1::contact_model();
  PeriodicBed        bed
    = cubic_lattice({Eigen::Vector3d::Zero()}, 2 * R * 0.97, 2, model);
  TangentCalculator  tangent;
  const CellTangents t = tangent.compute(bed, model);
  EXPECT_GT(t.affine(2, 2), 0.0);
  EXPECT_LT(relative_difference(t.condensed, t.affine), 1e-10);
}

/// Static condensation against central differences of the re-equilibrated
/// cell (the independent reference), at a loading and at an unloading
/// trial state of a disordered cell.
TEST(RveHomogenization, CondensedTangentEqualsFiniteDifference)
{
  const ContactModel model = material1::contact_model();
  for (const double trial : {-0.002, 0.0005})
    {
      PeriodicBed        bed = trial_state(model, uniaxial(trial));
      TangentCalculator  tangent;
      const CellTangents t = tangent.compute(bed, model);
      // Equilibrium to 1e-10 of the mean force (near round-off of the
      // unwrapped coordinates) and a strain step of 1e-6: the stress error
      // of the solves, ~1e-10 sigma / (C h), stays below 1e-5 relative.
      EquilibriumOptions tight;
      tight.force_tolerance = 1e-10;
      tight.step_tolerance  = 1e-10;
      const Matrix6d fd = finite_difference_tangent(bed, model, 1e-6, tight);
      EXPECT_LT(relative_difference(t.condensed, fd), 1e-4)
        << "trial strain " << trial << "\ncondensed\n"
        << t.condensed << "\nfinite difference\n"
        << fd;
      // The sparse direct solve gives the same condensation, to the
      // relative tolerance 1e-6 of the iterative solves.
      TangentCalculator  direct(TangentCalculator::Method::direct);
      const CellTangents d = direct.compute(bed, model);
      EXPECT_TRUE(d.direct);
      EXPECT_FALSE(t.direct);
      EXPECT_LT(relative_difference(d.condensed, t.condensed), 1e-5);
      // The fluctuations relax the cell: softer than affine.
      EXPECT_LT(t.condensed(2, 2), t.affine(2, 2));
      // Unloading is stiffer than plastic loading.
      const CellTangents u
        = tangent.compute(bed, model, ContactBranch::unloading);
      if (trial < 0.0)
        {
          EXPECT_GT(u.condensed(2, 2), 1.5 * t.condensed(2, 2));
        }
    }
}

/// A rigid rotation added to the deformation rotates the stress and
/// changes nothing else.
TEST(RveHomogenization, RigidRotationRotatesStressOnly)
{
  const ContactModel    model = material1::contact_model();
  PeriodicBed           bed   = trial_state(model, uniaxial(-0.002));
  const Eigen::Matrix3d sigma = love_weber_stress(bed);

  const Eigen::Matrix3d Q
    = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())
        .toRotationMatrix();
  PeriodicBed rotated = bed;
  map_affinely(rotated, Q * bed.deformation);
  ASSERT_TRUE(equilibrate_frozen(rotated, model, 1e-10).converged);
  const Eigen::Matrix3d expected = Q * sigma * Q.transpose();
  EXPECT_LT((love_weber_stress(rotated) - expected).norm(),
            1e-8 * sigma.norm());
  EXPECT_NEAR(rotated.relative_density(), bed.relative_density(), 1e-12);
  // No particle moved relative to its neighbours.
  for (const PeriodicContact &c : bed.contacts.pairs)
    EXPECT_NEAR(branch_vector(rotated.particles, rotated.cell, c).norm(),
                branch_vector(bed.particles, bed.cell, c).norm(),
                1e-9 * R);
}

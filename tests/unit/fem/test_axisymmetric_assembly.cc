#include "fem/axisymmetric_assembly.h"
#include "fem/fe_space.h"
#include "fem/isotropic_elasticity.h"
#include "fem/tablet_geometry.h"

#include <deal.II/base/function.h>
#include <deal.II/base/numbers.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace fem = compax::fem;

namespace
{
  constexpr double pi = dealii::numbers::PI;

  fem::TabletGeometry
  die()
  {
    fem::TabletGeometry g;
    g.die_diameter   = 10.0e-3;
    g.fill_height    = 4.2e-3;
    g.n_radial_cells = 5;
    return g;
  }

  /// The displacement field (u_r, u_z) = f(r, z), for interpolation.
  class Displacement : public dealii::Function<2>
  {
  public:
    explicit Displacement(
      std::function<dealii::Tensor<1, 2>(const dealii::Point<2> &)> f)
        : dealii::Function<2>(2)
        , f(std::move(f))
    {
    }

    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      return f(p)[c];
    }

  private:
    std::function<dealii::Tensor<1, 2>(const dealii::Point<2> &)> f;
  };

  /// Elastic stiffness on the r-z compact, and the forms K u and u^T K u.
  struct ElasticSystem
  {
    explicit ElasticSystem(unsigned int degree)
        : fe(dealii::FE_Q<2>(degree), 2)
    {
      fem::make_axisymmetric_compact(tria, die());
      space = std::make_unique<fem::FeSpace<2>>(tria, fe);
      constraints.close();
      fem::assemble_axisymmetric_elastic_stiffness(
        *space, fem::isotropic_stiffness_tensor(E, nu), constraints, K);
    }

    dealii::TrilinosWrappers::MPI::Vector
    interpolate(const Displacement &u) const
    {
      dealii::TrilinosWrappers::MPI::Vector v;
      space->reinit_vector(v);
      dealii::VectorTools::interpolate(space->dof_handler(), u, v);
      return v;
    }

    double
    energy_norm_squared(const dealii::TrilinosWrappers::MPI::Vector &u) const
    {
      dealii::TrilinosWrappers::MPI::Vector Ku(u);
      K.vmult(Ku, u);
      return u * Ku;
    }

    const double E  = 3.0e9; // typical of a compacted MCC tablet [Pa]
    const double nu = 0.28;
    dealii::Triangulation<2>               tria;
    dealii::FESystem<2>                    fe;
    std::unique_ptr<fem::FeSpace<2>>       space;
    dealii::AffineConstraints<double>      constraints;
    dealii::TrilinosWrappers::SparseMatrix K;
  };
} // namespace

TEST(TabletAssembly, MassMatrixGivesCylinderVolume)
{
  const fem::TabletGeometry g = die();
  const double exact          = pi * g.radius() * g.radius() * g.fill_height;
  for (const unsigned int degree : {1u, 2u})
    {
      dealii::Triangulation<2> tria;
      fem::make_axisymmetric_compact(tria, g);
      const dealii::FE_Q<2>             fe(degree);
      const fem::FeSpace<2>             space(tria, fe);
      dealii::AffineConstraints<double> constraints;
      constraints.close();
      dealii::TrilinosWrappers::SparseMatrix M;
      fem::assemble_axisymmetric_mass_matrix(space, constraints, M);
      EXPECT_EQ(M.m(), space.dof_handler().n_dofs());
      EXPECT_NEAR(fem::volume_from_mass_matrix(space, M) / exact, 1.0, 1e-12)
        << "degree " << degree;
    }
}

TEST(TabletAssembly, DistributedMassMatrixGivesCylinderVolume)
{
  const fem::TabletGeometry                       g = die();
  dealii::parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  fem::make_axisymmetric_compact(tria, g);
  tria.refine_global(2);
  const dealii::FE_Q<2>             fe(1);
  const fem::FeSpace<2>             space(tria, fe);
  dealii::AffineConstraints<double> constraints;
  constraints.close();
  dealii::TrilinosWrappers::SparseMatrix M;
  fem::assemble_axisymmetric_mass_matrix(space, constraints, M);
  const double exact = pi * g.radius() * g.radius() * g.fill_height;
  EXPECT_NEAR(fem::volume_from_mass_matrix(space, M) / exact, 1.0, 1e-12);
}

TEST(TabletAssembly, StiffnessAnnihilatesRigidAxialTranslation)
{
  for (const unsigned int degree : {1u, 2u})
    {
      const ElasticSystem sys(degree);
      const auto u = sys.interpolate(Displacement([](const dealii::Point<2> &) {
        return dealii::Tensor<1, 2>({0.0, 1.0e-6});
      }));
      dealii::TrilinosWrappers::MPI::Vector Ku(u);
      sys.K.vmult(Ku, u);
      // Round-off scale: |K|_inf |u|_inf.
      const double scale = sys.K.linfty_norm() * u.linfty_norm();
      EXPECT_GT(scale, 0.0);
      EXPECT_LT(Ku.linfty_norm(), 1e-13 * scale) << "degree " << degree;

      // A rigid radial shift is no rigid motion of a body of revolution:
      // it stretches the hoops (eps_tt = u_r / r), so it costs energy.
      const auto shift
        = sys.interpolate(Displacement([](const dealii::Point<2> &) {
            return dealii::Tensor<1, 2>({1.0e-6, 0.0});
          }));
      EXPECT_GT(sys.energy_norm_squared(shift), 0.0);
    }
}

TEST(TabletAssembly, UniformStrainEnergyMatchesClosedForm)
{
  const fem::TabletGeometry g = die();
  const double              V = pi * g.radius() * g.radius() * g.fill_height;
  const ElasticSystem       sys(1);
  const double lambda = sys.E * sys.nu / ((1 + sys.nu) * (1 - 2 * sys.nu));
  const double mu     = sys.E / (2 * (1 + sys.nu));

  // u_r = a r, u_z = b z: eps = diag(a, b, a) in (r, z, theta), uniform, and
  // exactly representable by Q1; u^T K u = eps : C : eps V.
  const double a = 2.0e-3, b = -7.0e-3;
  const auto   expansion
    = sys.interpolate(Displacement([a, b](const dealii::Point<2> &p) {
        return dealii::Tensor<1, 2>({a * p[0], b * p[1]});
      }));
  const double trace = 2 * a + b;
  const double w_exp
    = (lambda * trace * trace + 2 * mu * (2 * a * a + b * b)) * V;
  EXPECT_NEAR(sys.energy_norm_squared(expansion) / w_exp, 1.0, 1e-12);

  // u_r = 0, u_z = c r: uniform shear eps_rz = c / 2 and no hoop strain
  // (u_r = c z would add eps_tt = c z / r), so eps : C : eps = mu c^2.
  const double c = 1.5e-3;
  const auto   shear
    = sys.interpolate(Displacement([c](const dealii::Point<2> &p) {
        return dealii::Tensor<1, 2>({0.0, c * p[0]});
      }));
  EXPECT_NEAR(sys.energy_norm_squared(shear) / (mu * c * c * V), 1.0, 1e-12);
}

TEST(TabletAssembly, StiffnessIsSymmetric)
{
  const ElasticSystem sys(2);
  const auto u = sys.interpolate(Displacement([](const dealii::Point<2> &p) {
    return dealii::Tensor<1, 2>({std::sin(900 * p[1]), p[0] * p[0] * 1e3});
  }));
  const auto v = sys.interpolate(Displacement([](const dealii::Point<2> &p) {
    return dealii::Tensor<1, 2>({p[0] * p[1] * 1e2, std::cos(700 * p[0])});
  }));
  dealii::TrilinosWrappers::MPI::Vector Kv(v), Ku(u);
  sys.K.vmult(Kv, v);
  sys.K.vmult(Ku, u);
  EXPECT_NEAR((u * Kv) / (v * Ku), 1.0, 1e-12);
}

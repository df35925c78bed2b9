#include "fem/axisymmetric_assembly.h"

#include "fem/axisymmetric_kinematics.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <stdexcept>
#include <vector>

namespace compax::fem
{
  namespace
  {
    /**
     * Sizes @p matrix and assembles it from cell matrices: on every locally
     * owned cell, @p add_cell_terms(fe_values, cell_matrix) adds the cell's
     * integrals to the zeroed @p cell_matrix, with @p fe_values (QGauss of
     * degree + 1, @p flags and the JxW values) reinitialised there. The
     * cell matrices are distributed with @p constraints.
     */
    template <typename AddCellTerms>
    void
    assemble_cell_matrices(const FeSpace<2>                        &space,
                           const dealii::UpdateFlags                flags,
                           const dealii::AffineConstraints<double> &constraints,
                           dealii::TrilinosWrappers::SparseMatrix  &matrix,
                           AddCellTerms &&add_cell_terms)
    {
      space.reinit_matrix(matrix, constraints);
      const dealii::FiniteElement<2>              &fe = space.fe();
      const dealii::QGauss<2>                      quadrature(fe.degree + 1);
      dealii::FEValues<2>                          fe_values(fe,
                                    quadrature,
                                    flags | dealii::update_JxW_values);
      const unsigned int                           n = fe.n_dofs_per_cell();
      dealii::FullMatrix<double>                   cell_matrix(n, n);
      std::vector<dealii::types::global_dof_index> dof_indices(n);

      for (const auto &cell : space.dof_handler().active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          fe_values.reinit(cell);
          cell_matrix = 0.0;
          add_cell_terms(fe_values, cell_matrix);
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(cell_matrix,
                                                 dof_indices,
                                                 matrix);
        }
      matrix.compress(dealii::VectorOperation::add);
    }
  } // namespace

  void
  assemble_axisymmetric_mass_matrix(
    const FeSpace<2>                        &space,
    const dealii::AffineConstraints<double> &constraints,
    dealii::TrilinosWrappers::SparseMatrix  &matrix)
  {
    const dealii::FiniteElement<2> &fe = space.fe();
    const unsigned int              n  = fe.n_dofs_per_cell();
    assemble_cell_matrices(
      space,
      dealii::update_values | dealii::update_quadrature_points,
      constraints,
      matrix,
      [&](const dealii::FEValues<2>  &fe_values,
          dealii::FullMatrix<double> &cell_matrix) {
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double dV
              = axisymmetric_measure(fe_values.quadrature_point(q))
                * fe_values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int ci = fe.system_to_component_index(i).first;
                for (unsigned int j = 0; j < n; ++j)
                  if (fe.system_to_component_index(j).first == ci)
                    cell_matrix(i, j) += fe_values.shape_value(i, q)
                                         * fe_values.shape_value(j, q) * dV;
              }
          }
      });
  }

  void
  assemble_axisymmetric_elastic_stiffness(
    const FeSpace<2>                        &space,
    const dealii::SymmetricTensor<4, 3>     &C,
    const dealii::AffineConstraints<double> &constraints,
    dealii::TrilinosWrappers::SparseMatrix  &matrix)
  {
    const dealii::FiniteElement<2> &fe = space.fe();
    if (fe.n_components() != 2)
      throw std::invalid_argument(
        "axisymmetric elasticity needs a two-component (u_r, u_z) element");
    const dealii::FEValuesExtractors::Vector   displacement(0);
    const unsigned int                         n = fe.n_dofs_per_cell();
    std::vector<dealii::SymmetricTensor<2, 3>> eps(n);
    std::vector<dealii::SymmetricTensor<2, 3>> C_eps(n);
    assemble_cell_matrices(
      space,
      dealii::update_values | dealii::update_gradients
        | dealii::update_quadrature_points,
      constraints,
      matrix,
      [&](const dealii::FEValues<2>  &fe_values,
          dealii::FullMatrix<double> &cell_matrix) {
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const dealii::Point<2> &p = fe_values.quadrature_point(q);
            const double dV = axisymmetric_measure(p) * fe_values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              {
                eps[i]
                  = axisymmetric_strain(fe_values[displacement].gradient(i, q),
                                        fe_values[displacement].value(i, q),
                                        p[0]);
                C_eps[i] = C * eps[i];
              }
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) += (eps[i] * C_eps[j]) * dV;
          }
      });
  }

  double
  volume_from_mass_matrix(const FeSpace<2>                             &space,
                          const dealii::TrilinosWrappers::SparseMatrix &M)
  {
    if (space.fe().n_components() != 1)
      throw std::invalid_argument(
        "volume_from_mass_matrix needs the mass matrix of a scalar field");
    dealii::TrilinosWrappers::MPI::Vector ones;
    dealii::TrilinosWrappers::MPI::Vector M_ones;
    space.reinit_vector(ones);
    space.reinit_vector(M_ones);
    ones = 1.0;
    M.vmult(M_ones, ones);
    return ones * M_ones;
  }
} // namespace compax::fem

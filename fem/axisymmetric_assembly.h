#pragma once

#include "fem/fe_space.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

namespace compax::fem
{
  /**
   * Volume-weighted operators of the axisymmetric r-z model. Every integral
   * carries the measure 2 pi r dr dz, so the r-z mesh stands for the solid
   * of revolution and the results are true 3-D volumes, energies and forces.
   * Cells are integrated with QGauss(degree + 1) and deal.II's linear
   * mapping (the r-z compact has straight edges). Only locally owned cells
   * are assembled; the matrix is compressed on return.
   */

  /**
   * Gram ("mass" with unit density) matrix M_ij = int phi_i . phi_j dV of
   * the field of @p space. For a scalar field, 1^T M 1 is the volume of the
   * solid of revolution. @p matrix is sized here.
   * @param constraints applied while distributing cell contributions
   */
  void
  assemble_axisymmetric_mass_matrix(
    const FeSpace<2>                        &space,
    const dealii::AffineConstraints<double> &constraints,
    dealii::TrilinosWrappers::SparseMatrix  &matrix);

  /**
   * Small-strain elastic stiffness K_ij = int eps(phi_i) : C : eps(phi_j) dV
   * of a two-component (u_r, u_z) field of @p space, with the strain of
   * axisymmetric_strain() and a spatially uniform 3-D stiffness @p C [Pa]
   * in the (r, z, theta) basis. u^T K u is twice the strain energy [J] of
   * the displacement u [m]. @p matrix is sized here.
   */
  void
  assemble_axisymmetric_elastic_stiffness(
    const FeSpace<2>                        &space,
    const dealii::SymmetricTensor<4, 3>     &C,
    const dealii::AffineConstraints<double> &constraints,
    dealii::TrilinosWrappers::SparseMatrix  &matrix);

  /**
   * 1^T M 1 for the mass matrix @p M of a scalar field of @p space: the
   * volume [m^3] of the body (of revolution, for the r-z model). Uses
   * Trilinos matrix-vector products, so it works on distributed matrices.
   */
  double
  volume_from_mass_matrix(const FeSpace<2>                             &space,
                          const dealii::TrilinosWrappers::SparseMatrix &M);
} // namespace compax::fem

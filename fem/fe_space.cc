#include "fem/fe_space.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

namespace compax::fem
{
  template <int dim>
  FeSpace<dim>::FeSpace(const dealii::Triangulation<dim> &tria,
                        const dealii::FiniteElement<dim> &fe)
      : dofs(tria)
  {
    dofs.distribute_dofs(fe);
    owned    = dofs.locally_owned_dofs();
    relevant = dealii::DoFTools::extract_locally_relevant_dofs(dofs);
  }

  template <int dim>
  void
  FeSpace<dim>::distribute_dofs()
  {
    dofs.distribute_dofs(dofs.get_fe());
    owned    = dofs.locally_owned_dofs();
    relevant = dealii::DoFTools::extract_locally_relevant_dofs(dofs);
  }

  template <int dim>
  void
  FeSpace<dim>::reinit_matrix(
    dealii::TrilinosWrappers::SparseMatrix  &matrix,
    const dealii::AffineConstraints<double> &constraints) const
  {
    dealii::DynamicSparsityPattern dsp(relevant);
    dealii::DoFTools::make_sparsity_pattern(dofs,
                                            dsp,
                                            constraints,
                                            /*keep_constrained_dofs=*/false);
    dealii::SparsityTools::distribute_sparsity_pattern(dsp,
                                                       owned,
                                                       communicator(),
                                                       relevant);
    matrix.reinit(owned, owned, dsp, communicator());
  }

  template <int dim>
  void
  FeSpace<dim>::reinit_vector(
    dealii::TrilinosWrappers::MPI::Vector &vector) const
  {
    vector.reinit(owned, communicator());
  }

  template <int dim>
  void
  FeSpace<dim>::reinit_ghosted_vector(
    dealii::TrilinosWrappers::MPI::Vector &vector) const
  {
    vector.reinit(owned, relevant, communicator());
  }

  template class FeSpace<2>;
  template class FeSpace<3>;
} // namespace compax::fem

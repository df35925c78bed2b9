#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace compax::fem
{
  /**
   * A finite element field on a (serial or parallel::distributed) mesh
   * together with the Trilinos layout of its unknowns: the DoFHandler, the
   * locally owned and locally relevant index sets, and helpers that size
   * distributed matrices and vectors. The mesh must outlive it (the element
   * is copied). On a serial Triangulation every
   * process owns everything and the communicator is MPI_COMM_SELF.
   */
  template <int dim>
  class FeSpace
  {
  public:
    FeSpace(const dealii::Triangulation<dim> &tria,
            const dealii::FiniteElement<dim> &fe);

    /// Re-distributes the unknowns (call after the mesh changed).
    void
    distribute_dofs();

    const dealii::DoFHandler<dim> &
    dof_handler() const
    {
      return dofs;
    }

    const dealii::FiniteElement<dim> &
    fe() const
    {
      return dofs.get_fe();
    }

    MPI_Comm
    communicator() const
    {
      return dofs.get_triangulation().get_communicator();
    }

    const dealii::IndexSet &
    locally_owned_dofs() const
    {
      return owned;
    }

    const dealii::IndexSet &
    locally_relevant_dofs() const
    {
      return relevant;
    }

    /// Sizes @p matrix with the sparsity of this field under @p constraints
    /// (entries that constraints eliminate are left out).
    void
    reinit_matrix(dealii::TrilinosWrappers::SparseMatrix  &matrix,
                  const dealii::AffineConstraints<double> &constraints) const;

    /// Sizes @p vector to the locally owned unknowns (writable, no ghosts).
    void
    reinit_vector(dealii::TrilinosWrappers::MPI::Vector &vector) const;

    /// Sizes @p vector to owned plus ghost unknowns (read-only, for
    /// evaluating the field on locally owned cells).
    void
    reinit_ghosted_vector(dealii::TrilinosWrappers::MPI::Vector &vector) const;

  private:
    dealii::DoFHandler<dim> dofs;
    dealii::IndexSet        owned;
    dealii::IndexSet        relevant;
  };
} // namespace compax::fem

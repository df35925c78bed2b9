#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_assembler.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// Outcome of a FIRE relaxation.
  struct FireResult
  {
    int    iterations        = 0;
    double relative_residual = 0.0;
  };

  /**
   * Fast inertial relaxation (FIRE, Bitzek et al. 2006) of a bed towards
   * equilibrium, the fallback of the Newton solver while the bed is not
   * jammed: then K is singular along floppy mechanisms, the contacts being
   * formed have zero stiffness (P ~ gamma^{1+1/2m}), and Newton steps are
   * confined to the scale of the overlaps while particles must rearrange
   * over much larger distances. FIRE's inertia carries particles along flat
   * directions. Each particle's fictitious mass is its current diagonal
   * stiffness (floored at a fraction of the mean), so that a time step of
   * order one is stable everywhere; only residuals are evaluated between
   * mass updates.
   */
  class FireRelaxation
  {
  public:
    FireResult
    relax(Bed                &bed,
          const ContactModel &model,
          double              target_relative_residual,
          int                 max_iterations);

  private:
    ContactAssembler  assembler;
    BlockSparseMatrix K;
    Eigen::VectorXd   F, v, mass;
  };
} // namespace compax::dem

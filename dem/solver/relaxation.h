#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/equilibrium_system.h"
#include "dem/solver/residual_norms.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// Outcome of a relaxation (FIRE or L-BFGS).
  struct FireResult
  {
    bool        converged         = false;
    int         iterations        = 0;
    double      relative_residual = 0.0;
    ContactSums sums;
    /// Residual evaluations with the stiffness (mass updates).
    int assemblies = 0;

    /// Where the relaxation stands after @p evaluations residual
    /// evaluations, by the shared stopping test (relaxation_balance).
    void
    record(const RelaxationBalance &balance, const int evaluations)
    {
      relative_residual = balance.relative_residual;
      converged         = balance.balanced;
      iterations        = evaluations;
    }
  };

  /**
   * A minimiser of a bed's stored energy at fixed walls and internal
   * variables, driven by forces only: the solver of the states where Newton
   * cannot go (a loose bed's mechanisms, a stalled Newton iteration). FIRE
   * and L-BFGS solve this one problem to one stopping rule, so the
   * protocols choose between them through this interface.
   */
  class Relaxation
  {
  public:
    virtual ~Relaxation() = default;

    /**
     * Relaxes until max_i |F_i| <= target_relative_residual times the mean
     * contact force, or max_i |F_i| <= force_floor [N] (forces negligible
     * in absolute terms), or until @p budget iterations (FIRE) or residual
     * evaluations (L-BFGS).
     */
    virtual FireResult
    relax(EquilibriumSystem &system,
          double             target_relative_residual,
          int                budget,
          double             force_floor = 0.0)
      = 0;

    /// The same for a die bed.
    FireResult
    relax(Bed                &bed,
          const ContactModel &model,
          double              target_relative_residual,
          int                 budget,
          double              force_floor = 0.0);

  protected:
    /// Assembles the residual into @p F and the stiffness at the system's
    /// state, and returns each coordinate's inverse diagonal stiffness in
    /// @p inverse_diagonal: the inverse masses of FIRE and the
    /// preconditioner of L-BFGS.
    void
    assemble_inverse_diagonal(EquilibriumSystem &system,
                              Eigen::VectorXd   &F,
                              Eigen::VectorXd   &inverse_diagonal);

    ContactAssembler  assembler;
    BlockSparseMatrix K;
    ContactSums       sums;
  };
} // namespace compax::dem

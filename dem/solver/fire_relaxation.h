#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/equilibrium_system.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// Outcome of a FIRE relaxation.
  struct FireResult
  {
    bool        converged         = false;
    int         iterations        = 0;
    double      relative_residual = 0.0;
    ContactSums sums;
    /// Residual evaluations with the stiffness (mass updates).
    int assemblies = 0;
  };

  /**
   * Fast inertial relaxation (FIRE, Bitzek et al. 2006; semi-implicit
   * Euler) of a bed towards equilibrium at fixed walls and internal
   * variables. Used while the bed rearranges:
   * below jamming (consolidation) and as the fallback of the Newton solver
   * when it stalls. There K is singular along floppy mechanisms, contacts
   * being formed have zero stiffness (P ~ gamma^{1+1/2m}), and Newton steps
   * are confined to the scale of the overlaps while particles must move
   * farther; FIRE's inertia carries them along flat directions.
   *
   * Each particle's fictitious mass is its largest diagonal stiffness
   * (floored at 5 % of the mean, refreshed every 25 iterations), so that a
   * time step of order one is stable whatever the force scale. No particle
   * moves more than a tenth of the Verlet skin per iteration. Buffers are kept,
   * so repeated relaxations allocate nothing.
   */
  class FireRelaxation
  {
  public:
    /**
     * Relaxes until max_i |F_i| <= target_relative_residual times the mean
     * contact force, or max_i |F_i| <= force_floor [N] (forces negligible
     * in absolute terms), or max_iterations.
     */
    FireResult
    relax(EquilibriumSystem &system,
          double             target_relative_residual,
          int                max_iterations,
          double             force_floor = 0.0);

    /// The same for a die bed.
    FireResult
    relax(Bed                &bed,
          const ContactModel &model,
          double              target_relative_residual,
          int                 max_iterations,
          double              force_floor = 0.0);

  private:
    void
    update_masses(EquilibriumSystem &system);

    ContactAssembler  assembler;
    BlockSparseMatrix K;
    Eigen::VectorXd   F, v, inverse_mass;
    ContactSums       sums;
  };
} // namespace compax::dem

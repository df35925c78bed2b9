#pragma once

#include "dem/solver/relaxation.h"

#include <Eigen/Core>

namespace compax::dem
{
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
  class FireRelaxation final : public Relaxation
  {
  public:
    using Relaxation::relax;

    FireResult
    relax(EquilibriumSystem &system,
          double             target_relative_residual,
          int                max_iterations,
          double             force_floor = 0.0) override;

  private:
    Eigen::VectorXd F, v, inverse_mass;
  };
} // namespace compax::dem

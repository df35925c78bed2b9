#pragma once

#include "dem/rve/periodic_assembler.h"
#include "dem/solver/contact_bed_system.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// A periodic cell has no walls: nothing to limit beyond the pairs.
  inline bool
  limit_wall_closing(const PeriodicBed &,
                     const Eigen::VectorXd &,
                     double,
                     Eigen::VectorXd &)
  {
    return false;
  }

  /**
   * A periodic cell as an EquilibriumSystem, so that the die's trust-region
   * Newton and FIRE solve for the fluctuations at a fixed lattice. Rigid
   * translations are a null space of K; the residual is orthogonal to it,
   * which the Steihaug-Toint solves respect.
   */
  using PeriodicBedSystem = ContactBedSystem<PeriodicBed, PeriodicAssembler>;
} // namespace compax::dem

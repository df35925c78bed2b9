#pragma once

#include "dem/solver/contact_sums.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// max_i |F_i| over particles (F has 3 entries per particle).
  double
  max_particle_norm(const Eigen::VectorXd &F);

  /// max_i |F_i| / mean contact force, the convergence measure of the
  /// equilibrium solvers [-]: 0 for F = 0, infinite for a net force without
  /// loaded contacts.
  double
  relative_residual(const Eigen::VectorXd &F, const ContactSums &sums);

  /// Where a relaxation (FIRE, L-BFGS) stands against its stopping test.
  struct RelaxationBalance
  {
    /// max_i |F_i| / mean contact force, 0 without loaded contacts [-].
    double relative_residual = 0.0;
    /// max_i |F_i| <= target * mean contact force, or <= the force floor.
    bool balanced = false;
    /// max_i |F_i| [N].
    double largest_force = 0.0;
    /// The force below which max_i |F_i| is balanced: the larger of
    /// target * mean contact force and the force floor [N].
    double balanced_below = 0.0;
  };

  /// The stopping test the relaxations share: balanced to @p target [-]
  /// of the mean contact force, or every particle force below
  /// @p force_floor [N] (a loose bed whose contacts carry nothing).
  RelaxationBalance
  relaxation_balance(const Eigen::VectorXd &F,
                     const ContactSums     &sums,
                     double                 target,
                     double                 force_floor);
} // namespace compax::dem

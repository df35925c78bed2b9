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
} // namespace compax::dem

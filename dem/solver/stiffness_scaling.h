#pragma once

#include "dem/solver/block_sparse_matrix.h"

#include <Eigen/Core>

#include <cstddef>

namespace compax::dem
{
  /**
   * For each particle i, 1 / k_i in its three entries of `inverse`, k_i its
   * largest diagonal stiffness in K, floored at 5 % of the mean over the
   * bed (a particle without contacts gets that floor). FIRE uses it as the
   * inverse fictitious masses (a time step of order one is then stable
   * whatever the force scale), L-BFGS as its initial inverse Hessian.
   */
  void
  inverse_diagonal_stiffness(const BlockSparseMatrix &K,
                             std::size_t              n_particles,
                             Eigen::VectorXd         &inverse);
} // namespace compax::dem

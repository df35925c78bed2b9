#pragma once

#include "dem/solver/block_sparse_matrix.h"

#include <Eigen/Core>

#include <vector>

namespace compax::dem
{
  /**
   * Symmetric positive definite block-Jacobi preconditioner M built from
   * the 3x3 diagonal blocks of a possibly indefinite or singular stiffness:
   * each block's eigenvalues are replaced by max(|lambda|, floor), with
   * floor a small fraction of the mean block stiffness, so that rattlers
   * (zero blocks) and the negative geometric terms keep M SPD. M is scaled
   * to unit mean so that the M-norm of a step stays a length.
   */
  class BlockJacobiPreconditioner
  {
  public:
    void
    compute(const BlockSparseMatrix &K, double relative_floor = 1e-3);

    /// dst = M^{-1} src
    void
    solve(Eigen::VectorXd &dst, const Eigen::VectorXd &src) const;

    /// dst = M src
    void
    multiply(Eigen::VectorXd &dst, const Eigen::VectorXd &src) const;

    /// Mean stiffness the blocks were divided by [N/m].
    double
    scale() const
    {
      return scale_;
    }

  private:
    std::vector<double> m;     // 9 per block, M / scale
    std::vector<double> m_inv; // 9 per block, (M / scale)^{-1}
    double              scale_ = 1.0;
  };

  /// Outcome of one trust-region subproblem.
  struct SteihaugResult
  {
    /// Model decrease -(g.s + s.K s / 2) [J].
    double predicted_decrease = 0.0;
    /// M-norm of the step (M as scaled by the preconditioner) [m].
    double step_norm          = 0.0;
    int    iterations         = 0;
    bool   on_boundary        = false;
    bool   negative_curvature = false;
  };

  /**
   * Steihaug-Toint truncated preconditioned conjugate gradients for
   * min g.s + s.K s / 2 subject to |s|_M <= radius (Conn, Gould & Toint
   * 2000, Alg. 7.5.1): stops at the boundary, on negative curvature, or when
   * the preconditioned residual dropped by the factor `relative_tolerance`.
   * Buffers are kept between calls, so repeated solves allocate nothing.
   */
  class SteihaugCG
  {
  public:
    SteihaugResult
    solve(const BlockSparseMatrix         &K,
          const BlockJacobiPreconditioner &M,
          const Eigen::VectorXd           &g,
          double                           radius,
          double                           relative_tolerance,
          int                              max_iterations,
          Eigen::VectorXd                 &s);

  private:
    Eigen::VectorXd r, z, p, Kp, Ms, Mp;

    /// Largest tau >= 0 with |s + tau p|_M = radius.
    double
    to_boundary(const Eigen::VectorXd           &s,
                const Eigen::VectorXd           &p,
                const BlockJacobiPreconditioner &M,
                double                           radius);
  };
} // namespace compax::dem

#pragma once

#include "dem/solver/block_sparse_matrix.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
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

    /// dst = M^{-1} src. Inline, like multiply(), so that it compiles into
    /// the conjugate-gradient loop of every operator, not only of the
    /// assembled stiffness.
    void
    solve(Eigen::VectorXd &dst, const Eigen::VectorXd &src) const
    {
      block_diagonal_product(m_inv, dst, src);
    }

    /// dst = M src
    void
    multiply(Eigen::VectorXd &dst, const Eigen::VectorXd &src) const
    {
      block_diagonal_product(m, dst, src);
    }

    /// Mean stiffness the blocks were divided by [N/m].
    double
    scale() const
    {
      return scale_;
    }

  private:
    /// dst = blocks src for row-major 3x3 blocks.
    static void
    block_diagonal_product(const std::vector<double> &blocks,
                           Eigen::VectorXd           &dst,
                           const Eigen::VectorXd     &src)
    {
      const std::size_t n = blocks.size() / 9;
      for (std::size_t i = 0; i < n; ++i)
        {
          const double *a  = blocks.data() + 9 * i;
          const double *x  = src.data() + 3 * i;
          double       *y  = dst.data() + 3 * i;
          const double  x0 = x[0], x1 = x[1], x2 = x[2];
          y[0] = a[0] * x0 + a[1] * x1 + a[2] * x2;
          y[1] = a[3] * x0 + a[4] * x1 + a[5] * x2;
          y[2] = a[6] * x0 + a[7] * x1 + a[8] * x2;
        }
    }

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
   * K is any symmetric operator with vmult(dst, src), dst = K src: an
   * assembled stiffness, or a Jacobian applied matrix-free (the nonlocal
   * formulation's). Buffers are kept between calls, so repeated solves
   * allocate nothing.
   */
  class SteihaugCG
  {
  public:
    template <typename Operator>
    SteihaugResult
    solve(const Operator                  &K,
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

  template <typename Operator>
  SteihaugResult
  SteihaugCG::solve(const Operator                  &K,
                    const BlockJacobiPreconditioner &M,
                    const Eigen::VectorXd           &g,
                    const double                     radius,
                    const double                     relative_tolerance,
                    const int                        max_iterations,
                    Eigen::VectorXd                 &s)
  {
    const Eigen::Index n = g.size();
    s.setZero(n);
    r.resize(n);
    z.resize(n);
    p.resize(n);
    Kp.resize(n);
    Ms.resize(n);
    Mp.resize(n);

    SteihaugResult result;
    // K is in N/m; the preconditioner was scaled by M.scale(), so work with
    // K / scale to keep the model consistent with |s|_M.
    const double scale = M.scale();
    r                  = g / scale;
    M.solve(z, r);
    p                 = -z;
    double       rz   = r.dot(z);
    const double rz0  = rz;
    const double stop = relative_tolerance * relative_tolerance * rz0;

    if (rz0 > 0.0)
      for (int it = 0; it < max_iterations; ++it)
        {
          result.iterations = it + 1;
          K.vmult(Kp, p);
          Kp /= scale;
          const double curvature = p.dot(Kp);
          if (!(curvature > 0.0))
            {
              s += to_boundary(s, p, M, radius) * p;
              result.on_boundary        = true;
              result.negative_curvature = true;
              break;
            }
          const double alpha = rz / curvature;
          // |s + alpha p|_M >= radius ?
          M.multiply(Ms, s);
          M.multiply(Mp, p);
          const double ss = s.dot(Ms), sp = s.dot(Mp), pp = p.dot(Mp);
          if (ss + 2.0 * alpha * sp + alpha * alpha * pp >= radius * radius)
            {
              s += to_boundary(s, p, M, radius) * p;
              result.on_boundary = true;
              break;
            }
          s += alpha * p;
          r += alpha * Kp;
          M.solve(z, r);
          const double rz_new = r.dot(z);
          if (rz_new <= stop)
            break;
          p  = -z + (rz_new / rz) * p;
          rz = rz_new;
        }

    K.vmult(Kp, s);
    result.predicted_decrease = -(g.dot(s) + 0.5 * s.dot(Kp));
    M.multiply(Ms, s);
    result.step_norm = std::sqrt(std::max(s.dot(Ms), 0.0));
    return result;
  }
} // namespace compax::dem

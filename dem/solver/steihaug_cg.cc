#include "dem/solver/steihaug_cg.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  void
  BlockJacobiPreconditioner::compute(const BlockSparseMatrix &K,
                                     const double             relative_floor)
  {
    const std::size_t n = K.n_block_rows();
    m.resize(9 * n);
    m_inv.resize(9 * n);
    // Mean of the diagonal entries of the diagonal blocks.
    double trace_sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      {
        const double *b = K.block(K.diagonal_slot(i));
        trace_sum += std::abs(b[0]) + std::abs(b[4]) + std::abs(b[8]);
      }
    scale_             = n > 0 && trace_sum > 0.0 ? trace_sum / (3.0 * n) : 1.0;
    const double floor = relative_floor;

    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    for (std::size_t i = 0; i < n; ++i)
      {
        const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> b(
          K.block(K.diagonal_slot(i)));
        eig.computeDirect(b / scale_);
        Eigen::Vector3d lambda = eig.eigenvalues().cwiseAbs();
        for (int d = 0; d < 3; ++d)
          lambda[d] = std::max(lambda[d], floor);
        const Eigen::Matrix3d &V  = eig.eigenvectors();
        const Eigen::Matrix3d  Mi = V * lambda.asDiagonal() * V.transpose();
        const Eigen::Matrix3d  Mi_inv
          = V * lambda.cwiseInverse().asDiagonal() * V.transpose();
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            {
              m[9 * i + 3 * r + c]     = Mi(r, c);
              m_inv[9 * i + 3 * r + c] = Mi_inv(r, c);
            }
      }
  }

  double
  SteihaugCG::to_boundary(const Eigen::VectorXd           &s,
                          const Eigen::VectorXd           &p,
                          const BlockJacobiPreconditioner &M,
                          const double                     radius)
  {
    M.multiply(Ms, s);
    M.multiply(Mp, p);
    const double pp = p.dot(Mp), sp = s.dot(Mp), ss = s.dot(Ms);
    const double c = ss - radius * radius;
    if (pp <= 0.0)
      return 0.0;
    const double disc = std::sqrt(std::max(sp * sp - pp * c, 0.0));
    return (-sp + disc) / pp;
  }
} // namespace compax::dem

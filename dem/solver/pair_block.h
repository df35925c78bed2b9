#pragma once

#include "dem/contact/contact_response.h"
#include "dem/solver/block_sparse_matrix.h"

#include <Eigen/Core>

#include <cstdint>

namespace compax::dem
{
  /**
   * The 3x3 stiffness block of a central contact force P(gamma) between
   * two centres at separation d (gamma = R_i + R_j - |d|), written as
   * k = a n n^T + b I with n = d/|d|:
   * k = P' n n^T - P/|d| (I - n n^T), the normal term from the law's
   * exact dP/dgamma and the geometric term from the turning normal.
   */
  struct PairBlock
  {
    double a;
    double b;

    PairBlock(const ContactResponse &r, const double distance)
        : a(r.stiffness + r.force / distance)
        , b(-r.force / distance)
    {
    }

    /// The 9 row-major entries of a n n^T + b I into @p entries.
    void
    entries(const Eigen::Vector3d &n, double *entries) const
    {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          entries[3 * r + c] = a * n[r] * n[c] + (r == c ? b : 0.0);
    }

    /// block += sign * (a n n^T + b I), row-major 3x3.
    void
    add_to(double *block, const double sign, const Eigen::Vector3d &n) const
    {
      double k[9];
      entries(n, k);
      for (int e = 0; e < 9; ++e)
        block[e] += sign * k[e];
    }

    Eigen::Matrix3d
    matrix(const Eigen::Vector3d &n) const
    {
      return a * n * n.transpose() + b * Eigen::Matrix3d::Identity();
    }
  };

  /**
   * Adds a central pair force to the residual, F_i -= P n, F_j += P n
   * (n from j to i, |d| = distance), and, with K, its blocks: +k on the
   * diagonal blocks of i and j, -k on (i, j) and (j, i) at the given slots.
   */
  inline void
  scatter_pair(Eigen::VectorXd       &F,
               BlockSparseMatrix     *K,
               const std::uint32_t    i,
               const std::uint32_t    j,
               const std::size_t      slot_ij,
               const std::size_t      slot_ji,
               const Eigen::Vector3d &n,
               const double           distance,
               const ContactResponse &r)
  {
    F.segment<3>(3 * i) -= r.force * n;
    F.segment<3>(3 * j) += r.force * n;
    if (K == nullptr)
      return;
    const PairBlock blk(r, distance);
    blk.add_to(K->block(K->diagonal_slot(i)), 1.0, n);
    blk.add_to(K->block(K->diagonal_slot(j)), 1.0, n);
    blk.add_to(K->block(slot_ij), -1.0, n);
    blk.add_to(K->block(slot_ji), -1.0, n);
  }
} // namespace compax::dem

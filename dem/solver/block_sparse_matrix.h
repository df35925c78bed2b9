#pragma once

#include "dem/neighbors/cell_grid.h"
#include "dem/parallel_particles.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace compax::dem
{
  /**
   * Symmetric-pattern sparse matrix of 3x3 blocks in block compressed rows,
   * the stiffness of a particle system: one block row per particle, a
   * diagonal block for every particle and off-diagonal blocks (i, j) and
   * (j, i) for every pair contact. The pattern is built once per contact
   * list; assembly then only adds into fixed block slots, and the product
   * runs over flat arrays.
   */
  class BlockSparseMatrix
  {
  public:
    /// Builds the pattern for n block rows and the given pairs (i != j),
    /// which may repeat; values are zeroed.
    void
    reinit(std::size_t n, const std::vector<ParticlePair> &pairs);

    std::size_t
    n_block_rows() const
    {
      return row_start.empty() ? 0 : row_start.size() - 1;
    }

    std::size_t
    n_blocks() const
    {
      return columns.size();
    }

    /// Slot of block (i, j); it must be in the pattern.
    std::size_t
    slot(std::size_t i, std::size_t j) const;

    /// Slot of the diagonal block (i, i).
    std::size_t
    diagonal_slot(std::size_t i) const
    {
      return diagonal[i];
    }

    /// The 9 row-major values of a block.
    double *
    block(std::size_t slot)
    {
      return values.data() + 9 * slot;
    }

    const double *
    block(std::size_t slot) const
    {
      return values.data() + 9 * slot;
    }

    void
    set_zero();

    /// Zeroes the blocks of block row i only: a thread that owns the row
    /// clears it before it assembles into it.
    void
    set_row_zero(std::size_t i)
    {
      std::fill(values.begin() + 9 * std::size_t{row_start[i]},
                values.begin() + 9 * std::size_t{row_start[i + 1]},
                0.0);
    }

    /// dst = A src; the same to the bit on any number of threads.
    void
    vmult(Eigen::VectorXd &dst, const Eigen::VectorXd &src) const;

    /// The same matrix as an Eigen sparse matrix (tests, direct solvers).
    Eigen::SparseMatrix<double>
    to_sparse() const;

  private:
    std::vector<std::uint32_t> row_start;
    std::vector<std::uint32_t> columns;
    std::vector<std::uint32_t> diagonal;
    std::vector<double>        values;
  };
} // namespace compax::dem

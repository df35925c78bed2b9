#pragma once

#include "dem/solver/block_sparse_matrix.h"

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /**
   * The sparsity pattern of a stiffness K for a list of pair contacts and
   * the slots of their off-diagonal blocks (i, j) and (j, i), rebuilt only
   * when the contact list (its revision), the number of particles or the
   * matrix changed. Shared by the die's and the periodic cell's
   * assemblers; a pair listed several times (periodic images) shares its
   * blocks.
   */
  class PairPattern
  {
  public:
    template <typename Pairs>
    void
    refresh(const std::size_t   n_particles,
            const std::uint64_t revision,
            const Pairs        &pairs,
            BlockSparseMatrix  &K)
    {
      // The matrix's size as well as its address: another matrix may
      // live at the address of one destroyed since.
      if (revision == pattern_revision && &K == pattern_matrix
          && K.n_block_rows() == n_particles && K.n_blocks() == pattern_blocks)
        return;
      scratch.clear();
      scratch.reserve(pairs.size());
      for (const auto &c : pairs)
        scratch.emplace_back(c.i, c.j);
      K.reinit(n_particles, scratch);
      slots.resize(2 * pairs.size());
      for (std::size_t k = 0; k < pairs.size(); ++k)
        {
          slots[2 * k]     = K.slot(pairs[k].i, pairs[k].j);
          slots[2 * k + 1] = K.slot(pairs[k].j, pairs[k].i);
        }
      pattern_revision = revision;
      pattern_matrix   = &K;
      pattern_blocks   = K.n_blocks();
    }

    /// Slot of block (i, j) of pair k.
    std::uint32_t
    ij(const std::size_t k) const
    {
      return slots[2 * k];
    }

    /// Slot of block (j, i) of pair k.
    std::uint32_t
    ji(const std::size_t k) const
    {
      return slots[2 * k + 1];
    }

  private:
    std::uint64_t              pattern_revision = ~std::uint64_t(0);
    const BlockSparseMatrix   *pattern_matrix   = nullptr;
    std::size_t                pattern_blocks   = 0;
    std::vector<std::uint32_t> slots;
    std::vector<ParticlePair>  scratch;
  };
} // namespace compax::dem

#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_sums.h"
#include "dem/solver/pair_pattern.h"
#include "dem/solver/pair_terms.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /**
   * The law's response(gamma, a_p, a_B) evaluated inline: the plastic
   * branch for any m, the elastic branch and the bridge for m = 2 with
   * a^{1/2} and a_p^{1/2} by sqrt instead of pow (libm's pow dominated the
   * profile of the residual); otherwise delegated to the law. The same
   * formulas, equal to round-off (tests/unit/dem/test_solver_consolidation
   * compares both on every branch).
   */
  ContactResponse
  contact_response(const BondedElastoplasticLaw &law,
                   double                        gamma,
                   const ContactHistory         &history);

  /**
   * Residual and stiffness of the static equilibrium of Gonzalez 2018,
   * Eq. (12), at fixed walls and fixed internal variables.
   *
   * The residual is the out-of-balance internal force
   * F_i = - sum_j P_ij n_ij (n_ij = (x_i - x_j)/|x_i - x_j|), the gradient
   * of the bed's stored energy, so that equilibrium is F = 0 and
   * K = dF/dx is symmetric. A pair contributes the block
   * k = P' n n^T - P/d (I - n n^T) to (i,i) and (j,j) and -k to (i,j) and
   * (j,i): the normal term from the law's exact dP/dgamma and the
   * geometric term from the turning normal. A punch contributes P' n n^T;
   * the die wall also P/r (I - e_r e_r^T) restricted to the horizontal
   * plane, because its normal turns with the particle.
   */
  class ContactAssembler
  {
  public:
    /// F only (refreshes the contact list if needed).
    ContactSums
    residual(Bed &bed, const ContactModel &model, Eigen::VectorXd &F);

    /// F and K; the pattern of K is rebuilt only when the contact list
    /// changed.
    ContactSums
    assemble(Bed                &bed,
             const ContactModel &model,
             Eigen::VectorXd    &F,
             BlockSparseMatrix  &K);

    /**
     * Beds with at least this many candidate pairs evaluate the pairs of a
     * residual on every OpenMP thread, each into its own force vector, and
     * sum those in thread order (the same result for the same thread
     * count). Below it the threads' start and the sum of their vectors
     * cost about what they save.
     */
    static constexpr std::size_t parallel_pairs = 20000;

  private:
    template <bool with_stiffness>
    ContactSums
    evaluate(const Bed &bed, Eigen::VectorXd &F, BlockSparseMatrix *K);

    /// The pairs' forces into F on every thread (residual only).
    void
    add_pair_forces_in_parallel(const Bed       &bed,
                                Eigen::VectorXd &F,
                                LoadedContacts  &loaded);

    PairPattern pattern;
    /// Per-thread force vectors and sums of add_pair_forces_in_parallel,
    /// kept between calls so that a residual allocates nothing.
    std::vector<Eigen::VectorXd> thread_forces;
    std::vector<LoadedContacts>  thread_loaded;
  };
} // namespace compax::dem

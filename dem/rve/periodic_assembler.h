#pragma once

#include "dem/rve/periodic_bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/contact_sums.h"
#include "dem/solver/pair_pattern.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /// Which branch of the contact law the stiffness follows.
  enum class ContactBranch
  {
    /// The law's tangent at the current state and history (plastic where
    /// the contact is loading): the consistent tangent of the next step.
    current,
    /// Elastic unloading everywhere: contacts on the plastic branch take
    /// the unloading stiffness 16 E* a / (3 pi) (the elastic moduli).
    unloading
  };

  /// Response of a periodic contact at overlap gamma on the given branch:
  /// the law's, with the elastic unloading stiffness 16 E* a / (3 pi)
  /// where the contact is on the plastic branch and `unloading` is asked.
  ContactResponse
  periodic_contact_response(const PeriodicContact &c,
                            double                 gamma,
                            ContactBranch          branch);

  /**
   * Residual F and stiffness K = dF/dx of a periodic cell at fixed lattice
   * and internal variables: the pair terms of the die's ContactAssembler
   * with the branch vector taken to the contact's image. A pair (i, j)
   * touching through several images adds all of them to the same blocks.
   */
  class PeriodicAssembler
  {
  public:
    /// F only (refreshes the contact list if needed).
    ContactSums
    residual(PeriodicBed &bed, const ContactModel &model, Eigen::VectorXd &F);

    /// F and K; the pattern of K is rebuilt only when the list changed.
    ContactSums
    assemble(PeriodicBed        &bed,
             const ContactModel &model,
             Eigen::VectorXd    &F,
             BlockSparseMatrix  &K,
             ContactBranch       branch = ContactBranch::current);

  private:
    template <bool with_stiffness>
    ContactSums
    evaluate(const PeriodicBed &bed,
             Eigen::VectorXd   &F,
             BlockSparseMatrix *K,
             ContactBranch      branch);


    PairPattern pattern;
  };
} // namespace compax::dem

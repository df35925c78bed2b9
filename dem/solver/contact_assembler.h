#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/contact_sums.h"
#include "dem/solver/pair_assembler.h"
#include "dem/solver/pair_terms.h"
#include "dem/solver/wall_terms.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// Refreshes the contact list of a bed in a die if needed.
  inline void
  update_contacts(Bed &bed, const ContactModel &model)
  {
    bed.contacts.update(bed.particles, bed.walls, model);
  }

  /// Residual and stiffness of a bed in a die (PairAssembler).
  using ContactAssembler = PairAssembler<Bed>;

  extern template class PairAssembler<Bed>;
} // namespace compax::dem

#pragma once

#include "dem/rve/periodic_bed.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/pair_assembler.h"

#include <Eigen/Core>

#include <limits>

namespace compax::dem
{
  /// Refreshes the contact list of a periodic cell if needed.
  inline void
  update_contacts(PeriodicBed &bed, const ContactModel &model)
  {
    bed.contacts.update(bed.particles, bed.cell, model);
  }

  /// A periodic cell's residual is the serial sum of its pairs.
  template <>
  inline constexpr std::size_t parallel_residual_pairs<
    PeriodicBed> = std::numeric_limits<std::size_t>::max();

  /// Response of a periodic contact at overlap gamma on the given branch
  /// (contact_response()).
  inline ContactResponse
  periodic_contact_response(const PeriodicContact &c,
                            const double           gamma,
                            const ContactBranch    branch)
  {
    return contact_response(c, gamma, branch);
  }

  /// Residual and stiffness of a periodic cell at fixed lattice
  /// (PairAssembler): the pair terms with the branch vector taken to the
  /// contact's image.
  using PeriodicAssembler = PairAssembler<PeriodicBed>;

  extern template class PairAssembler<PeriodicBed>;
} // namespace compax::dem

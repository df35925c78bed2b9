#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/contact_bed_system.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// The punches' and the die wall's part of limit_closing(): lowers
  /// factor[i] so that no particle's step closes its gap to a virgin wall
  /// contact by more than that gap plus `allowance`; returns whether it did.
  bool
  limit_wall_closing(const Bed             &bed,
                     const Eigen::VectorXd &s,
                     double                 allowance,
                     Eigen::VectorXd       &factor);

  /// A bed in a die as an EquilibriumSystem: the particles between the
  /// punches and the die wall, with the contact law of a ContactModel.
  using DieBedSystem = ContactBedSystem<Bed, ContactAssembler>;
} // namespace compax::dem

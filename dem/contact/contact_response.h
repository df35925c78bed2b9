#pragma once

#include "dem/contact/contact_history.h"

/**
 * @file
 * The value types every contact law returns and keeps.
 *
 * Sign conventions (design notes): the overlap, or relative approach,
 * gamma = R1 + R2 - |x1 - x2| is positive in compression; the normal force P
 * is positive when repulsive and negative when a solid bridge or adhesion
 * pulls the bodies together.
 */

namespace compax::dem
{
  /**
   * What a contact law evaluates at one overlap: the force, its exact
   * derivative with respect to the overlap, and the contact radius.
   */
  struct ContactResponse
  {
    /// Normal force P [N], positive repulsive.
    double force = 0.0;
    /// Exact derivative dP/dgamma [N/m]; the equilibrium solver relies on it.
    double stiffness = 0.0;
    /// Contact radius a [m].
    double contact_radius = 0.0;
  };

  /**
   * Information from outside the pair that some laws need: the nonlocal
   * overlap gamma_NL of Gonzalez & Cuitino 2012 (Eq. 9), and the particle
   * pressure P_ij of Giannis 2021 (Eq. 13). Local laws ignore it.
   */
  struct ContactContext
  {
    /// Nonlocal overlap gamma_NL [m] induced by the other contacts.
    double nonlocal_overlap = 0.0;
    /// Mean particle pressure P_ij = (tr sigma_i + tr sigma_j)/3 [Pa],
    /// positive in tension as tr(sigma) is.
    double particle_pressure = 0.0;
  };
} // namespace compax::dem

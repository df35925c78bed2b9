#pragma once

#include "dem/contact/bonded_elastoplastic.h"

#include <cstddef>

namespace compax::dem
{
  /// Bonds created and broken by one history update (Eq. 13).
  struct BondChanges
  {
    std::size_t formed = 0;
    std::size_t broken = 0;
  };

  /// Whether a contact keeps internal variables (plastic radius or bond).
  inline bool
  has_history(const ContactHistory &h)
  {
    return h.a_p > 0.0 || h.a_B > 0.0;
  }

  /**
   * Applies Eq. (13) to one contact at overlap gamma and counts the bond
   * it forms or breaks. A contact whose force |P| is not above
   * `resolution` [N] (the equilibrium solve's force resolution) keeps its
   * plastic radius: the solve determines no force there (an unjammed
   * region's exact equilibrium is force-free), so its left-over overlap
   * is not plastic deformation (Eq. 13 at the converged state, with the
   * forces the solve resolves). Breakage (a = 0) always applies.
   */
  void
  update_history(const BondedElastoplasticLaw &law,
                 double                        gamma,
                 ContactHistory               &history,
                 BondChanges                  &changes,
                 double                        resolution = 0.0);
} // namespace compax::dem

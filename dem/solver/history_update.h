#pragma once

#include "dem/contact/particle_law.h"

#include <cstddef>

namespace compax::dem
{
  /// Bonds created and broken by one history update (Eq. 13).
  struct BondChanges
  {
    std::size_t formed = 0;
    std::size_t broken = 0;
  };

  /**
   * Applies the law's history update (Eq. 13 for the bonded law) to one
   * contact at overlap gamma and counts the bond it forms or breaks. A
   * contact that loads plastically with a force |P| not above
   * `resolution` [N] (the equilibrium solve's force resolution) keeps its
   * internal variables: the solve determines no force there (an unjammed
   * region's exact equilibrium is force-free), so its left-over overlap
   * is not plastic deformation (Eq. 13 at the converged state, with the
   * forces the solve resolves). Breakage (a = 0) always applies.
   */
  void
  update_history(const ParticleLaw &law,
                 double             gamma,
                 ContactHistory    &history,
                 BondChanges       &changes,
                 double             resolution = 0.0);
} // namespace compax::dem

#include "dem/solver/history_update.h"

#include <cmath>

namespace compax::dem
{
  void
  update_history(const ParticleLaw &law,
                 const double       gamma,
                 ContactHistory    &history,
                 BondChanges       &changes,
                 const double       resolution)
  {
    if (resolution > 0.0 && loads_plastically(law, gamma, history)
        && std::abs(law_response(law, gamma, history).force) <= resolution)
      return;
    const ContactHistory next       = updated_history(law, gamma, history);
    const bool           was_bonded = bonded(law, history);
    const bool           is_bonded  = bonded(law, next);
    if (!was_bonded && is_bonded)
      ++changes.formed;
    else if (was_bonded && !is_bonded)
      ++changes.broken;
    history = next;
  }
} // namespace compax::dem

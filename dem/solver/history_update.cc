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
    const ContactHistory next = updated_history(law, gamma, history);
    if (history.a_B == 0.0 && next.a_B > 0.0)
      ++changes.formed;
    else if (history.a_B > 0.0 && next.a_B == 0.0)
      ++changes.broken;
    history = next;
  }
} // namespace compax::dem

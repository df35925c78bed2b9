#include "dem/solver/history_update.h"

#include <cmath>

namespace compax::dem
{
  void
  update_history(const BondedElastoplasticLaw &law,
                 const double                  gamma,
                 ContactHistory               &history,
                 BondChanges                  &changes,
                 const double                  resolution)
  {
    if (resolution > 0.0)
      {
        const ContactResponse r = law.response(gamma, history.a_p, history.a_B);
        if (r.contact_radius > history.a_p && std::abs(r.force) <= resolution)
          return;
      }
    const ContactHistory next = law.updated_history(gamma, history);
    if (history.a_B == 0.0 && next.a_B > 0.0)
      ++changes.formed;
    else if (history.a_B > 0.0 && next.a_B == 0.0)
      ++changes.broken;
    history = next;
  }
} // namespace compax::dem

#pragma once

#include "dem/contact/contact_law.h"

namespace compax::dem
{
  /**
   * The part of ContactLaw that every local law without internal variables
   * shares (Hertz, plastic hardening): no context, a history that converged
   * states leave as it was, and the force, stiffness and radius from the
   * law's own `response(gamma)`. The law derives as
   * `class L final : public HistoryFreeLaw<L>`, so the particle solvers'
   * calls on an L stay direct.
   */
  template <typename Law>
  class HistoryFreeLaw : public ContactLaw
  {
  public:
    /// A local law: the particle solvers may hold it (particle_law.h).
    static constexpr bool needs_context = false;

    using ContactLaw::evaluate;
    using ContactLaw::updated_history;

    ContactResponse
    evaluate(double gamma,
             const ContactHistory &,
             const ContactContext &) const override
    {
      return static_cast<const Law &>(*this).response(gamma);
    }

    /// No internal variables: the history is returned unchanged.
    ContactHistory
    updated_history(double,
                    const ContactHistory &history,
                    const ContactContext &) const override
    {
      return history;
    }
  };
} // namespace compax::dem

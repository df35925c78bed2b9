#pragma once

#include "dem/contact/contact_response.h"

#include <limits>
#include <string>
#include <vector>

namespace compax::dem
{
  /**
   * Interface of a normal contact law between two bodies whose pair
   * properties (radii, materials) were fixed at construction.
   *
   * Two operations, kept apart on purpose: evaluate() is a pure function of
   * the overlap and the current history (trial states of a Newton iteration
   * call it freely), and updated_history() returns the internal variables
   * of a converged state (Gonzalez 2018, Eq. 13), which the caller stores.
   *
   * The concrete laws are final classes with inline-able members, so the
   * particle solver may also call them without the virtual dispatch.
   */
  class ContactLaw
  {
  public:
    virtual ~ContactLaw() = default;

    /// Force, exact stiffness dP/dgamma and contact radius at overlap
    /// gamma [m] for the given history and context.
    virtual ContactResponse
    evaluate(double                gamma,
             const ContactHistory &history,
             const ContactContext &context) const = 0;

    /// Internal variables after a converged step that ends at overlap gamma.
    virtual ContactHistory
    updated_history(double                gamma,
                    const ContactHistory &history,
                    const ContactContext &context) const = 0;

    /**
     * Stiffness dP/dgamma [N/m] of the branch that a contact at overlap
     * gamma would follow if it unloaded from there: the elastic moduli of
     * a compacted bed. A law without plastic loading keeps its own
     * stiffness (the default).
     */
    virtual double
    unloading_stiffness(double                gamma,
                        const ContactHistory &history,
                        const ContactContext &context) const
    {
      return evaluate(gamma, history, context).stiffness;
    }

    /**
     * Whether the state at overlap gamma loads the contact plastically, so
     * that updated_history() would grow its internal variables (a_p of a
     * bonded contact, delta_max of a hysteretic spring). Converged states
     * whose force the solve does not resolve skip such growth
     * (history_update.h). False for laws without history (the default).
     */
    virtual bool
    loads_plastically(double                gamma,
                      const ContactHistory &history,
                      const ContactContext &context) const
    {
      (void)gamma;
      (void)history;
      (void)context;
      return false;
    }

    /**
     * The largest separation -gamma [m] at which a contact with this
     * history can still carry a force: farther apart, its force and
     * stiffness are exactly zero. A particle solver sets such pairs aside
     * while they stay that far apart (ContactSet::dormant). Infinite by
     * default, so that a law that does not declare it is never set aside.
     */
    virtual double
    separation_reach(const ContactHistory &history,
                     const ContactContext &context) const
    {
      (void)history;
      (void)context;
      return std::numeric_limits<double>::infinity();
    }

    /// The internal variables the law keeps, slot k of ContactHistory
    /// being the k-th; none for an elastic law (the default).
    virtual std::vector<HistoryVariable>
    history_variables() const
    {
      return {};
    }

    /// Whether the contact holds a solid bridge (counted as a bond in the
    /// bed's statistics); false for laws without bonds (the default).
    virtual bool
    bonded(const ContactHistory &history) const
    {
      (void)history;
      return false;
    }

    /// Short name used in parameter files and output ("hertz", ...).
    virtual std::string
    name() const = 0;

    /// Convenience overloads for laws that need no context.
    ContactResponse
    evaluate(double gamma, const ContactHistory &history) const
    {
      return evaluate(gamma, history, ContactContext{});
    }

    ContactHistory
    updated_history(double gamma, const ContactHistory &history) const
    {
      return updated_history(gamma, history, ContactContext{});
    }
  };
} // namespace compax::dem

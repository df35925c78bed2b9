#pragma once

#include "dem/contact/contact_law.h"
#include "dem/contact/law_parameter.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace compax::dem
{
  /// The two bodies a law is built between: radii [m], Young's moduli [Pa]
  /// and Poisson's ratios [-]; for a wall the second body has
  /// compax::dem::rigid radius and modulus.
  struct ContactBodies
  {
    double R1 = 0.0, E1 = 0.0, nu1 = 0.0;
    double R2 = 0.0, E2 = 0.0, nu2 = 0.0;
  };

  /// The context of a law at overlap gamma [m] (ContactContext).
  using ContactContextAt = std::function<ContactContext(double gamma)>;

  /**
   * A contact law as the command line offers it: its name, its parameters
   * (declared by the law itself) and how to build it between two bodies.
   * A law joins every command that reads the registry through its entry in
   * RegisteredLaws (registered_laws.h).
   */
  struct RegisteredContactLaw
  {
    /// Value of the Law selection, e.g. "walton-braun".
    std::string name;
    /// One sentence for the selection's documentation.
    std::string description;
    /// Subsection of the law's parameters.
    std::string               subsection;
    std::vector<LawParameter> parameters;
    /// The law between the bodies for the parsed parameters.
    std::function<std::unique_ptr<ContactLaw>(const LawParameterValues &values,
                                              const ContactBodies      &bodies)>
      make;
    /// The context the law needs at each overlap of an isolated pair (a
    /// nonlocal overlap, a particle pressure); empty: none.
    std::function<ContactContextAt(const LawParameterValues &values,
                                   const ContactBodies      &bodies)>
      context;
    /// Whether the law is the contact of the materials' elastic spheres
    /// (E, nu), so that the nonlocal formulation of Gonzalez & Cuitino 2012,
    /// whose far field is that of elastic spheres, may be layered on it. A
    /// law that keeps internal variables or needs a context is refused
    /// there whatever this says.
    bool elastic_bodies = false;
  };

  /// The laws built from their own declarations, in the order offered.
  const std::vector<RegisteredContactLaw> &
  registered_contact_laws();

  /// The registered law called @p name, or nullptr.
  const RegisteredContactLaw *
  find_contact_law(const std::string &name);
} // namespace compax::dem

#pragma once

#include "dem/contact/contact_law.h"
#include "dem/contact/law_parameter.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace compax::dem
{
  /**
   * A contact law as the command line offers it: its name, its parameters
   * (declared by the law itself) and how to build it between two bodies.
   * A law joins every command that reads the registry through one line of
   * registered_contact_laws().
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
    /// The law between bodies of radii R1 and R2 [m] (R2 =
    /// compax::dem::rigid for a wall) for the parsed parameters.
    std::function<std::unique_ptr<ContactLaw>(const LawParameterValues &values,
                                              double                    R1,
                                              double                    R2)>
      make;
  };

  /// The laws built from their own declarations, in the order offered.
  const std::vector<RegisteredContactLaw> &
  registered_contact_laws();

  /// The registered law called @p name, or nullptr.
  const RegisteredContactLaw *
  find_contact_law(const std::string &name);
} // namespace compax::dem

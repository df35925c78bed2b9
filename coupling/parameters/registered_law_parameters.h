#pragma once

// The parameters of the registered contact laws (dem/contact/
// contact_law_registry.h) as .prm entries: each law's subsection, declared
// from the law's own declarations, and the parsed values handed back.

#include "dem/contact/contact_law_registry.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace compax::coupling
{
  /// Declares the subsection of every registered law that has parameters
  /// (@p local_only: only the laws the particle solvers can hold, those
  /// without a context).
  void
  declare_registered_laws(dealii::ParameterHandler &prm, bool local_only);

  /// The parsed values of @p law's subsection.
  dem::LawParameterValues
  get_registered_law_values(dealii::ParameterHandler        &prm,
                            const dem::RegisteredContactLaw &law);

  /// "|name1|name2...": the registered laws' names for a Selection.
  std::string
  registered_law_names(bool local_only);

  /// "; name (description; subsection S)..." for a Selection's
  /// documentation.
  std::string
  registered_law_documentation(bool local_only);
} // namespace compax::coupling

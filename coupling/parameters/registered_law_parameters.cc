#include "coupling/parameters/registered_law_parameters.h"

#include "input/input_error.h"
#include "input/parameter_declaration.h"
#include "input/parameter_file.h"
#include "input/real_interval.h"

namespace compax::coupling
{
  namespace
  {
    bool
    offered(const dem::RegisteredContactLaw &law, const bool local_only)
    {
      return !local_only || !law.context;
    }
  } // namespace

  void
  declare_registered_laws(dealii::ParameterHandler &prm, const bool local_only)
  {
    for (const dem::RegisteredContactLaw &law : dem::registered_contact_laws())
      {
        if (law.parameters.empty() || !offered(law, local_only))
          continue;
        prm.enter_subsection(law.subsection);
        for (const dem::LawParameter &p : law.parameters)
          input::declare_quantity(
            prm,
            p.name,
            input::format_number(p.default_value),
            input::RealInterval(p.lower, p.lower_open, p.upper, p.upper_open),
            p.unit,
            p.documentation);
        prm.leave_subsection();
      }
  }

  dem::LawParameterValues
  get_registered_law_values(dealii::ParameterHandler        &prm,
                            const dem::RegisteredContactLaw &law)
  {
    dem::LawParameterValues values;
    if (law.parameters.empty())
      return values;
    prm.enter_subsection(law.subsection);
    for (const dem::LawParameter &p : law.parameters)
      values[p.name] = prm.get_double(p.name);
    prm.leave_subsection();
    return values;
  }

  std::string
  registered_law_names(const bool local_only)
  {
    std::string names;
    for (const dem::RegisteredContactLaw &law : dem::registered_contact_laws())
      if (offered(law, local_only))
        names += "|" + law.name;
    return names;
  }

  std::string
  registered_law_documentation(const bool local_only)
  {
    std::string text;
    for (const dem::RegisteredContactLaw &law : dem::registered_contact_laws())
      if (offered(law, local_only))
        text += "; " + law.name + ": " + law.description
                + (law.parameters.empty()
                     ? std::string()
                     : " (subsection " + law.subsection + ")");
    return text;
  }
} // namespace compax::coupling

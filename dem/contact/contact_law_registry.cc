#include "dem/contact/contact_law_registry.h"

#include "dem/contact/registered_laws.h"

namespace compax::dem
{
  namespace
  {
    template <typename... Laws>
    std::vector<RegisteredContactLaw>
    registrations(LawList<Laws...>)
    {
      return {Laws::registration()...};
    }
  } // namespace

  const std::vector<RegisteredContactLaw> &
  registered_contact_laws()
  {
    static const std::vector<RegisteredContactLaw> laws
      = registrations(RegisteredLaws{});
    return laws;
  }

  const RegisteredContactLaw *
  find_contact_law(const std::string &name)
  {
    for (const RegisteredContactLaw &law : registered_contact_laws())
      if (law.name == name)
        return &law;
    return nullptr;
  }
} // namespace compax::dem

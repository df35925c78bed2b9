#include "dem/contact/contact_law_registry.h"

#include "dem/contact/hertz.h"
#include "dem/contact/multicontact_adhesive.h"
#include "dem/contact/nonlocal_hertz.h"
#include "dem/contact/walton_braun.h"

namespace compax::dem
{
  const std::vector<RegisteredContactLaw> &
  registered_contact_laws()
  {
    static const std::vector<RegisteredContactLaw> laws = {
      HertzLaw::registration(),
      NonlocalHertzLaw::registration(),
      MulticontactAdhesiveLaw::registration(),
      WaltonBraunLaw::registration(),
    };
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

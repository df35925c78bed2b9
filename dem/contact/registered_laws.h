#pragma once

#include "dem/contact/hertz.h"
#include "dem/contact/multicontact_adhesive.h"
#include "dem/contact/nonlocal_hertz.h"
#include "dem/contact/plastic_hardening.h"
#include "dem/contact/walton_braun.h"

/**
 * @file
 * The list of contact laws offered by name. A law joins the registry
 * (`compax contact`, the generated documentation) and, if it needs no
 * context (`needs_context == false`), the particle solvers of `compax die`
 * and `compax rve` (particle_law.h) through its one entry here.
 */

namespace compax::dem
{
  /// A compile-time list of law types.
  template <typename... Laws>
  struct LawList
  {
  };

  /// Every registered law, in the order offered.
  using RegisteredLaws = LawList<HertzLaw,
                                 NonlocalHertzLaw,
                                 MulticontactAdhesiveLaw,
                                 WaltonBraunLaw,
                                 PlasticHardeningLaw>;
} // namespace compax::dem

#pragma once

#include "dem/contact/contact_law_registry.h"
#include "dem/solver/contact_model.h"

namespace compax::testing
{
  /// Material 1's elastic constants (Gonzalez 2018, Table 1) with the
  /// registry's Walton-Braun law at its defaults, k2_max/k1 = @p ratio and
  /// plasticity depth phi_F = @p depth.
  inline dem::ContactModel
  walton_braun_model(const double ratio = 22.0, const double depth = 0.573)
  {
    dem::ContactModel model(dem::ElastoplasticMaterial{5e9, 0.25, 150e6, 2.0},
                            0.0);
    const dem::RegisteredContactLaw *law
      = dem::find_contact_law("walton-braun");
    dem::LawParameterValues values;
    for (const dem::LawParameter &p : law->parameters)
      values[p.name] = p.default_value;
    values["Unloading stiffness ratio"] = ratio;
    values["Plasticity depth"]          = depth;
    model.use_registered_law(*law, values);
    return model;
  }
} // namespace compax::testing

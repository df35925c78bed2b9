#include "fem/material_registry.h"

#include "fem/drucker_prager_cap.h"
#include "fem/linear_elastic_material.h"

#include <stdexcept>

namespace compax::fem
{
  void
  MaterialRegistry::add(RegisteredMaterial material)
  {
    for (const RegisteredMaterial &m : list)
      if (m.name == material.name)
        throw std::logic_error("continuum material '" + material.name
                               + "' registered twice");
    list.push_back(std::move(material));
  }

  const RegisteredMaterial &
  MaterialRegistry::find(const std::string &name) const
  {
    for (const RegisteredMaterial &m : list)
      if (m.name == name)
        return m;
    throw std::out_of_range("no continuum material named '" + name + "'");
  }

  std::string
  MaterialRegistry::selection() const
  {
    std::string names;
    for (const RegisteredMaterial &m : list)
      names += (names.empty() ? "" : "|") + m.name;
    return names;
  }

  std::string
  MaterialRegistry::documentation() const
  {
    std::string text;
    for (const RegisteredMaterial &m : list)
      text += (text.empty() ? "" : "; ") + m.name + ": " + m.description;
    return text;
  }

  void
  MaterialRegistry::declare_parameters(dealii::ParameterHandler &prm) const
  {
    for (const RegisteredMaterial &m : list)
      if (m.declare)
        m.declare(prm);
  }

  MaterialRegistry
  closed_form_materials()
  {
    MaterialRegistry r;
    r.add({"drucker-prager-cap",
           "the density-dependent Drucker-Prager Cap of DPC table",
           &DruckerPragerCap::declare_parameters,
           &DruckerPragerCap::parse_parameters});
    r.add({"linear-elastic",
           "linear hypoelasticity with Young's modulus and Poisson's ratio",
           &LinearElasticMaterial::declare_parameters,
           &LinearElasticMaterial::parse_parameters});
    return r;
  }
} // namespace compax::fem

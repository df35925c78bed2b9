#include "dem/solver/contact_model.h"

#include "dem/contact/pair_properties.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

namespace compax::dem
{
  ContactModel::ContactModel(const ElastoplasticMaterial &material,
                             const double                 fracture_toughness,
                             const double                 regularization)
      : ContactModel(std::vector<ElastoplasticMaterial>{material},
                     {{fracture_toughness}},
                     regularization)
  {
  }

  ContactModel::ContactModel(std::vector<ElastoplasticMaterial> materials_,
                             std::vector<std::vector<double>>   toughness_,
                             const double                       regularization)
      : regularization(regularization)
      , materials(std::move(materials_))
      , toughness(std::move(toughness_))
  {
    if (materials.empty())
      throw std::invalid_argument("a contact model needs a material");
    if (toughness.size() != materials.size())
      throw std::invalid_argument("K_Ic table size differs from the number "
                                  "of materials");
    for (const auto &row : toughness)
      if (row.size() != materials.size())
        throw std::invalid_argument("K_Ic table is not square");
  }

  void
  ContactModel::set_fracture_toughness(const double fracture_toughness)
  {
    for (auto &row : toughness)
      std::fill(row.begin(), row.end(), fracture_toughness);
  }

  void
  ContactModel::use_registered_law(const RegisteredContactLaw &law,
                                   LawParameterValues          values)
  {
    if (law.context)
      throw std::invalid_argument(
        "the contact law " + law.name
        + " needs a context (a nonlocal overlap or a particle pressure) "
          "that the particle solvers do not provide");
    registered        = &law;
    registered_values = std::move(values);
    // Built once here so that a law this build cannot hold fails now.
    const ElastoplasticMaterial &m = materials.front();
    registered_law_between({1.0,
                            m.youngs_modulus,
                            m.poisson_ratio,
                            1.0,
                            m.youngs_modulus,
                            m.poisson_ratio});
  }

  ParticleLaw
  ContactModel::registered_law_between(const ContactBodies &bodies) const
  {
    const std::unique_ptr<ContactLaw> law
      = registered->make(registered_values, bodies);
    std::optional<ParticleLaw> held = as_particle_law(*law);
    if (!held)
      throw std::invalid_argument("the contact law " + registered->name
                                  + " is not among the particle solvers' "
                                    "laws (particle_law.h)");
    return *held;
  }

  std::string
  ContactModel::law_name() const
  {
    // Any pair: every contact of the model follows the same law.
    return std::visit([](const auto &law) { return law.name(); },
                      pair_law(0, 1.0, 0, 1.0));
  }

  ParticleLaw
  ContactModel::pair_law(const unsigned int material_i,
                         const double       R_i,
                         const unsigned int material_j,
                         const double       R_j) const
  {
    if (registered)
      {
        const ElastoplasticMaterial &a = materials[material_i];
        const ElastoplasticMaterial &b = materials[material_j];
        return registered_law_between({R_i,
                                       a.youngs_modulus,
                                       a.poisson_ratio,
                                       R_j,
                                       b.youngs_modulus,
                                       b.poisson_ratio});
      }
    return BondedElastoplasticLaw::for_pair(materials[material_i],
                                            R_i,
                                            materials[material_j],
                                            R_j,
                                            toughness[material_i][material_j],
                                            regularization,
                                            regularized);
  }

  ParticleLaw
  ContactModel::wall_law(const unsigned int material_i, const double R_i) const
  {
    const ElastoplasticMaterial &m = materials[material_i];
    if (registered)
      return registered_law_between(
        {R_i, m.youngs_modulus, m.poisson_ratio, rigid, rigid, 0.0});
    return BondedElastoplasticLaw::for_pair(
      m,
      R_i,
      ElastoplasticMaterial::rigid_wall(m.plastic_exponent),
      rigid,
      wall_bonding ? toughness[material_i][material_i] : 0.0,
      regularization,
      regularized);
  }
} // namespace compax::dem

#include "dem/solver/contact_model.h"

#include "dem/contact/pair_properties.h"

#include <stdexcept>

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

  BondedElastoplasticLaw
  ContactModel::pair_law(const unsigned int material_i,
                         const double       R_i,
                         const unsigned int material_j,
                         const double       R_j) const
  {
    return BondedElastoplasticLaw::for_pair(materials[material_i],
                                            R_i,
                                            materials[material_j],
                                            R_j,
                                            toughness[material_i][material_j],
                                            regularization,
                                            regularized);
  }

  BondedElastoplasticLaw
  ContactModel::wall_law(const unsigned int material_i, const double R_i) const
  {
    const ElastoplasticMaterial &m = materials[material_i];
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

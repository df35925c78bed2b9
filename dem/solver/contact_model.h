#pragma once

#include "dem/contact/contact_law_registry.h"
#include "dem/contact/elastoplastic_material.h"
#include "dem/contact/particle_law.h"

#include <string>
#include <vector>

namespace compax::dem
{
  /**
   * Which law acts between two particles, or a particle and a rigid wall,
   * of a bed made of several materials: the bonded elasto-plastic law of
   * Gonzalez 2018 (Eq. 4) with a fracture toughness K_Ic per pair of
   * materials, or a registered law that needs no context
   * (use_registered_law()). Solid bridges with the walls are off unless
   * asked for.
   */
  class ContactModel
  {
  public:
    /// One material: K_Ic for contacts with itself, xi_B = 0.01.
    explicit ContactModel(const ElastoplasticMaterial &material,
                          double                       fracture_toughness,
                          double                       regularization = 0.01);

    /// Several materials; toughness[a][b] = K_Ic between materials a and b
    /// (symmetric) [Pa m^1/2].
    ContactModel(std::vector<ElastoplasticMaterial> materials,
                 std::vector<std::vector<double>>   toughness,
                 double                             regularization = 0.01);

    std::size_t
    n_materials() const
    {
      return materials.size();
    }

    const ElastoplasticMaterial &
    material(unsigned int a) const
    {
      return materials[a];
    }

    double
    fracture_toughness(unsigned int a, unsigned int b) const
    {
      return toughness[a][b];
    }

    /// Sets K_Ic [Pa m^1/2] between every pair of materials; everything
    /// else (materials, walls, a registered law) stays.
    void
    set_fracture_toughness(double fracture_toughness);

    /// Solid bridges with the punches and the die wall, using the K_Ic of
    /// the particle's material with itself (default off).
    bool wall_bonding = false;

    /// Use the regularized law (Eq. 4); false selects Eq. (2).
    bool regularized = true;

    /// xi_B [-].
    double regularization;

    /**
     * Every contact follows the registered law @p law with the parsed
     * @p values instead of the bonded law; the bodies' radii, Young's
     * moduli and Poisson's ratios come from the materials. Throws
     * std::invalid_argument if the law needs a context (a nonlocal
     * overlap, a particle pressure) that the particle solvers do not
     * provide.
     */
    void
    use_registered_law(const RegisteredContactLaw &law,
                       LawParameterValues          values);

    /// The registered law every contact follows, or nullptr for the
    /// bonded law.
    const RegisteredContactLaw *
    registered_law() const
    {
      return registered;
    }

    /// The name of the law every contact follows (ContactLaw::name(), e.g.
    /// bonded-elastoplastic), for output that says which law it holds.
    std::string
    law_name() const;

    ParticleLaw
    pair_law(unsigned int material_i,
             double       R_i,
             unsigned int material_j,
             double       R_j) const;

    /// Law of a particle against a rigid flat (punch or die wall; the die
    /// wall's curvature is neglected in the law, R_die >> R).
    ParticleLaw
    wall_law(unsigned int material_i, double R_i) const;

  private:
    ParticleLaw
    registered_law_between(const ContactBodies &bodies) const;

    std::vector<ElastoplasticMaterial> materials;
    std::vector<std::vector<double>>   toughness;
    const RegisteredContactLaw        *registered = nullptr;
    LawParameterValues                 registered_values;
  };
} // namespace compax::dem

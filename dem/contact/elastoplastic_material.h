#pragma once

namespace compax::dem
{
  /**
   * Constitutive constants of one elasto-plastic particle species
   * (Gonzalez 2018, Sec. 2 and Table 1): power-law hardening
   * sigma = kappa epsilon^{1/m}.
   */
  struct ElastoplasticMaterial
  {
    /// Young's modulus E [Pa].
    double youngs_modulus = 0.0;
    /// Poisson's ratio nu [-].
    double poisson_ratio = 0.0;
    /// Plastic stiffness kappa [Pa].
    double plastic_stiffness = 0.0;
    /// Plastic law exponent m >= 1 [-].
    double plastic_exponent = 1.0;

    /// A rigid flat: infinite E and kappa, so that it drops out of every
    /// mixing rule; m is that of the particle it touches.
    static ElastoplasticMaterial
    rigid_wall(double plastic_exponent);
  };

  /**
   * Fracture toughness of a solid bridge between two materials from their
   * interfacial fracture energies and the plastic dissipation (Gonzalez 2018,
   * formula after Eq. 5): K_Ic = sqrt(2 (omega1 + omega2 + G_p) E) with E the
   * effective plane-strain modulus of the pair.
   *
   * @param omega1, omega2 interfacial fracture energies [J/m^2]
   * @param plastic_dissipation G_p [J/m^2]
   * @return K_Ic [Pa m^{1/2}]
   */
  double
  fracture_toughness_from_energies(const ElastoplasticMaterial &material1,
                                   double                       omega1,
                                   const ElastoplasticMaterial &material2,
                                   double                       omega2,
                                   double plastic_dissipation);
} // namespace compax::dem

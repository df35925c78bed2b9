#include "dem/contact/plastic_hardening.h"

#include "dem/contact/pair_properties.h"

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace compax::dem
{
  PlasticHardeningLaw::PlasticHardeningLaw(const BondedElastoplasticLaw &branch)
      : loading(branch)
  {
  }

  PlasticHardeningLaw
  PlasticHardeningLaw::for_pair(const double      R1,
                                const double      R2,
                                const Parameters &parameters)
  {
    if (!(parameters.plastic_stiffness > 0.0))
      throw std::invalid_argument("plastic-hardening: kappa must be positive");
    if (!(parameters.plastic_exponent >= 1.0))
      throw std::invalid_argument("plastic-hardening: m must be at least 1");
    // The elastic constants only enter the bonded law's unloading branch,
    // which this law never takes: any finite values serve.
    ElastoplasticMaterial particle;
    particle.youngs_modulus    = 1.0;
    particle.poisson_ratio     = 0.0;
    particle.plastic_stiffness = parameters.plastic_stiffness;
    particle.plastic_exponent  = parameters.plastic_exponent;
    const ElastoplasticMaterial other
      = std::isinf(R2)
          ? ElastoplasticMaterial::rigid_wall(parameters.plastic_exponent)
          : particle;
    return PlasticHardeningLaw(BondedElastoplasticLaw::for_pair(
      particle, R1, other, R2, 0.0, 0.0, false));
  }

  RegisteredContactLaw
  PlasticHardeningLaw::registration()
  {
    const double         inf = std::numeric_limits<double>::infinity();
    RegisteredContactLaw r;
    r.name        = "plastic-hardening";
    r.description = "spheres with power-law hardening plastic behaviour, no "
                    "elastic unloading and no bonding: the plastic loading "
                    "branch of Gonzalez 2018, Eqs. 1-2, at every overlap (the "
                    "law of the study its Section 5.1 cites for K_Ic = 0)";
    r.subsection  = "Plastic hardening";
    r.parameters  = {{"Plastic stiffness",
                      150e6,
                      0.0,
                      true,
                      inf,
                      true,
                      "Pa",
                      "kappa > 0: the plastic stiffness of both bodies "
                       "(150e6 Pa: Material 1 of Gonzalez 2018, Table 1; "
                       "900e6 Pa for Material 2)."},
                     {"Plastic exponent",
                      2.0,
                      1.0,
                      false,
                      inf,
                      true,
                      "-",
                      "m >= 1: the plastic law exponent (2 for both "
                       "materials of Gonzalez 2018)."}};
    r.make        = [](const LawParameterValues &v, const ContactBodies &b) {
      Parameters p;
      p.plastic_stiffness = v.at("Plastic stiffness");
      p.plastic_exponent  = v.at("Plastic exponent");
      return std::make_unique<PlasticHardeningLaw>(for_pair(b.R1, b.R2, p));
    };
    return r;
  }
} // namespace compax::dem

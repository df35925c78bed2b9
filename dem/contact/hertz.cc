#include "dem/contact/hertz.h"

#include "dem/contact/pair_properties.h"

#include <cmath>
#include <memory>

namespace compax::dem
{
  HertzLaw::HertzLaw(const double effective_radius,
                     const double effective_modulus)
      : R(effective_radius)
      , E(effective_modulus)
      , n_H(4.0 / 3.0 * effective_modulus * std::sqrt(effective_radius))
  {
  }

  HertzLaw
  HertzLaw::for_pair(const double R1,
                     const double E1,
                     const double nu1,
                     const double R2,
                     const double E2,
                     const double nu2)
  {
    return HertzLaw(dem::effective_radius(R1, R2),
                    dem::effective_modulus(E1, nu1, E2, nu2));
  }

  RegisteredContactLaw
  HertzLaw::registration()
  {
    RegisteredContactLaw r;
    r.name           = "hertz";
    r.description    = "elastic spheres";
    r.subsection     = "Hertz";
    r.elastic_bodies = true;
    r.make           = [](const LawParameterValues &, const ContactBodies &b) {
      return std::make_unique<HertzLaw>(
        for_pair(b.R1, b.E1, b.nu1, b.R2, b.E2, b.nu2));
    };
    return r;
  }
} // namespace compax::dem

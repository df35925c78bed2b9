#include "dem/solver/contact_assembler.h"

#include "dem/numbers.h"

#include <cmath>

#include <omp.h>

namespace compax::dem
{
  ContactResponse
  contact_response(const BondedElastoplasticLaw &law,
                   const double                  gamma,
                   const ContactHistory         &h)
  {
    // Plastic loading (Gonzalez 2018 Eq. 3 with a >= a_p) written out as in
    // BondedElastoplasticLaw::response, with a^{1/m} = sqrt(a) for m = 2
    // (libm's pow dominated the profile of the residual).
    const auto  &k  = law.constants();
    const double c2 = law.c_squared();
    const double R  = k.effective_radius;
    if (gamma > 0.0 && gamma >= h.a_p * h.a_p / (2.0 * c2 * R))
      {
        const double a     = std::sqrt(2.0 * c2 * R * gamma);
        const double inv_m = 1.0 / k.plastic_exponent;
        const double a_pow_m
          = k.plastic_exponent == 2.0 ? std::sqrt(a) : std::pow(a, inv_m);
        const double n_p = k.plastic_coefficient;
        return {n_p * a * a * a_pow_m,
                n_p * (2.0 + inv_m) * c2 * R * a_pow_m,
                a};
      }
    if (h.a_p == 0.0)
      return {};
    if (k.plastic_exponent != 2.0)
      return law.response(gamma, h.a_p, h.a_B);

    // Elastic (un)loading and the solid bridge (Eq. 4), as in
    // BondedElastoplasticLaw::response, with a_p^{1/2} by sqrt.
    const double n_p      = k.plastic_coefficient;
    const double a_p      = h.a_p;
    const double root_ap  = std::sqrt(a_p);
    const double gamma_p  = a_p * a_p / (2.0 * c2 * R);
    const double alpha    = 4.0 * k.effective_modulus / (3.0 * n_p * root_ap);
    const double recovery = alpha * (gamma_p - gamma);
    const double a2       = a_p * a_p - recovery * recovery;
    if (a2 <= 0.0)
      return {};
    const double    a = std::sqrt(a2);
    const double    x = a / a_p;
    ContactResponse r;
    r.contact_radius = a;
    r.force          = 2.0 * n_p / pi * a_p * a_p * root_ap
              * (std::asin(x) - x * std::sqrt(1.0 - x * x));
    r.stiffness = 16.0 * k.effective_modulus * a / (3.0 * pi);
    if (k.fracture_toughness > 0.0 && h.a_B > 0.0
        && (a < h.a_B || !k.regularized))
      {
        const double root_a  = std::sqrt(a);
        double       scale   = 2.0 * k.fracture_toughness * std::sqrt(pi);
        double       g       = a * root_a;
        double       dg_da_a = 1.5 / root_a;
        if (k.regularized)
          {
            const double xi    = k.regularization;
            const double gap   = h.a_B - a;
            const double denom = (1.0 + xi) * h.a_B - a;
            scale *= (1.0 + xi) * (1.0 + xi);
            g *= gap / denom;
            dg_da_a = 1.5 * gap / (root_a * denom)
                      - xi * h.a_B * root_a / (denom * denom);
          }
        r.force -= scale * g;
        r.stiffness -= scale * dg_da_a * alpha * alpha * (gamma_p - gamma);
      }
    return r;
  }

  double
  unloading_stiffness(const BondedElastoplasticLaw &law, const double a)
  {
    return 16.0 * law.constants().effective_modulus * a / (3.0 * pi);
  }

  template class PairAssembler<Bed>;
} // namespace compax::dem

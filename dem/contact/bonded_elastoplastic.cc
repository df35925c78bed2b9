#include "dem/contact/bonded_elastoplastic.h"

#include "dem/contact/pair_properties.h"
#include "dem/numbers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  BondedElastoplasticLaw::BondedElastoplasticLaw(const PairConstants &constants)
      : k(constants)
      , c2(1.43 * std::exp(-0.97 / constants.plastic_exponent))
      , inverse_m(1.0 / constants.plastic_exponent)
  {
  }

  BondedElastoplasticLaw
  BondedElastoplasticLaw::for_pair(const ElastoplasticMaterial &material1,
                                   const double                 R1,
                                   const ElastoplasticMaterial &material2,
                                   const double                 R2,
                                   const double fracture_toughness,
                                   const double regularization,
                                   const bool   regularized)
  {
    const double m = material1.plastic_exponent;
    if (material2.plastic_exponent != m)
      throw std::invalid_argument(
        "the bonded elasto-plastic law needs one plastic exponent m for both "
        "bodies of a pair");
    const double  R   = effective_radius(R1, R2);
    const double  k_m = 3.0 * std::pow(6.0, -1.0 / m);
    PairConstants c;
    c.effective_radius  = R;
    c.effective_modulus = effective_modulus(material1.youngs_modulus,
                                            material1.poisson_ratio,
                                            material2.youngs_modulus,
                                            material2.poisson_ratio);
    c.plastic_exponent  = m;
    c.plastic_coefficient
      = pi * k_m * std::pow(R, -1.0 / m)
        * effective_plastic_stiffness(material1.plastic_stiffness,
                                      material2.plastic_stiffness,
                                      m);
    c.fracture_toughness = fracture_toughness;
    c.regularization     = regularization;
    c.regularized        = regularized;
    return BondedElastoplasticLaw(c);
  }

  double
  BondedElastoplasticLaw::plastic_overlap(const double a_p) const
  {
    return a_p * a_p / (2.0 * c2 * k.effective_radius);
  }

  double
  BondedElastoplasticLaw::plastic_radius(const double gamma) const
  {
    return gamma > 0.0 ? std::sqrt(2.0 * c2 * k.effective_radius * gamma) : 0.0;
  }

  double
  BondedElastoplasticLaw::breakage_overlap(const double a_p) const
  {
    return plastic_overlap(a_p)
           - 3.0 * k.plastic_coefficient * std::pow(a_p, 1.0 + inverse_m)
               / (4.0 * k.effective_modulus);
  }

  double
  BondedElastoplasticLaw::bonding_energy_ratio(const double a_p) const
  {
    const double n_p = k.plastic_coefficient;
    return 4.0 * pi * k.fracture_toughness * k.fracture_toughness
           / (n_p * n_p * std::pow(a_p, 1.0 + 2.0 * inverse_m));
  }

  double
  BondedElastoplasticLaw::contact_radius(const double gamma,
                                         const double a_p) const
  {
    const double gamma_p = plastic_overlap(a_p);
    if (gamma >= gamma_p)
      return plastic_radius(gamma);
    const double recovery
      = 4.0 * k.effective_modulus * (gamma_p - gamma)
        / (3.0 * k.plastic_coefficient * std::pow(a_p, inverse_m));
    return std::sqrt(std::max(a_p * a_p - recovery * recovery, 0.0));
  }

  ContactResponse
  BondedElastoplasticLaw::response(const double gamma,
                                   const double a_p,
                                   const double a_B) const
  {
    if (a_p == 0.0 && gamma <= 0.0)
      return {}; // virgin and apart (most candidates of a Verlet list)
    const double n_p     = k.plastic_coefficient;
    const double gamma_p = plastic_overlap(a_p);

    if (gamma >= gamma_p)
      {
        // Plastic loading (also virgin contact, a_p = 0, gamma > 0).
        if (gamma <= 0.0)
          return {};
        const double a       = plastic_radius(gamma);
        const double a_pow_m = root_m(a);
        return {n_p * a * a * a_pow_m,
                n_p * (2.0 + inverse_m) * c2 * k.effective_radius * a_pow_m,
                a};
      }

    // Elastic (un)loading: a^2 = a_p^2 - (alpha (gamma_p - gamma))^2.
    const double alpha = 4.0 * k.effective_modulus / (3.0 * n_p * root_m(a_p));
    const double recovery = alpha * (gamma_p - gamma);
    const double a2       = a_p * a_p - recovery * recovery;
    if (a2 <= 0.0)
      return {};
    const double a = std::sqrt(a2);
    const double x = a / a_p;

    ContactResponse r;
    r.contact_radius = a;
    r.force          = 2.0 * n_p / pi * a_p * a_p * root_m(a_p)
              * (std::asin(x) - x * std::sqrt(1.0 - x * x));
    r.stiffness = 16.0 * k.effective_modulus * a / (3.0 * pi);

    if (k.fracture_toughness > 0.0 && a_B > 0.0 && (a < a_B || !k.regularized))
      {
        // Solid bridge: P_B = 2 K sqrt(pi) (1+xi)^2 g(a), with
        // g = a^{3/2} (a_B - a) / ((1+xi) a_B - a) (regularized, Eq. 4) or
        // g = a^{3/2} (Eq. 2), and da/dgamma = alpha^2 (gamma_p - gamma) / a;
        // the 1/a is folded into dg/da / a.
        const double root_a  = std::sqrt(a);
        double       scale   = 2.0 * k.fracture_toughness * std::sqrt(pi);
        double       g       = a * root_a;
        double       dg_da_a = 1.5 / root_a;
        if (k.regularized)
          {
            const double xi    = k.regularization;
            const double gap   = a_B - a;
            const double denom = (1.0 + xi) * a_B - a;
            scale *= (1.0 + xi) * (1.0 + xi);
            g *= gap / denom;
            dg_da_a = 1.5 * gap / (root_a * denom)
                      - xi * a_B * root_a / (denom * denom);
          }
        r.force -= scale * g;
        r.stiffness -= scale * dg_da_a * alpha * alpha * (gamma_p - gamma);
      }
    return r;
  }

  ContactResponse
  BondedElastoplasticLaw::evaluate(const double          gamma,
                                   const ContactHistory &history,
                                   const ContactContext &) const
  {
    return response(gamma, a_p(history), a_B(history));
  }

  ContactHistory
  BondedElastoplasticLaw::history(const double a_p, const double a_B)
  {
    ContactHistory h;
    h[a_p_slot] = a_p;
    h[a_B_slot] = a_B;
    return h;
  }

  ContactHistory
  BondedElastoplasticLaw::updated_history(const double          gamma,
                                          const ContactHistory &history,
                                          const ContactContext &) const
  {
    ContactHistory next = history;
    const double   a    = contact_radius(gamma, a_p(history));
    if (a > a_p(history))
      {
        next[a_p_slot] = a;
        next[a_B_slot] = k.fracture_toughness > 0.0 ? a : 0.0;
      }
    else if (a == 0.0)
      next[a_B_slot] = 0.0;
    return next;
  }

  double
  BondedElastoplasticLaw::separation_reach(const ContactHistory &history,
                                           const ContactContext &) const
  {
    if (a_p(history) == 0.0)
      return 0.0; // virgin: no force apart
    return std::max(-breakage_overlap(a_p(history)), 0.0);
  }

  double
  BondedElastoplasticLaw::unloading_stiffness(const double          gamma,
                                              const ContactHistory &history,
                                              const ContactContext &) const
  {
    const ContactResponse r = response(gamma, a_p(history), a_B(history));
    if (r.contact_radius > 0.0 && r.contact_radius >= a_p(history))
      return 16.0 * k.effective_modulus * r.contact_radius / (3.0 * pi);
    return r.stiffness;
  }

  bool
  BondedElastoplasticLaw::loads_plastically(const double          gamma,
                                            const ContactHistory &history,
                                            const ContactContext &) const
  {
    return response(gamma, a_p(history), a_B(history)).contact_radius
           > a_p(history);
  }
} // namespace compax::dem

#include "dem/contact/nonlocal_hertz.h"

#include "dem/contact/pair_properties.h"
#include "dem/numbers.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace compax::dem
{
  double
  nonlocal_compliance(const double theta,
                      const double R,
                      const double E,
                      const double nu)
  {
    const double RE = R * E;
    if (std::isinf(RE))
      return 0.0;
    const double h = std::sin(0.5 * theta);
    return (1.0 + nu) / (4.0 * pi * RE)
           * (-2.0 * (1.0 - nu) - 2.0 * (1.0 - 2.0 * nu) * h
              + (7.0 - 8.0 * nu) * h * h)
           / h;
  }

  double
  nonlocal_displacement(const double P,
                        const double theta,
                        const double R,
                        const double E,
                        const double nu)
  {
    return P * nonlocal_compliance(theta, R, E, nu);
  }

  double
  nonlocal_displacement_derivative(const double theta,
                                   const double R,
                                   const double E,
                                   const double nu)
  {
    return nonlocal_compliance(theta, R, E, nu);
  }

  NonlocalHertzLaw::NonlocalHertzLaw(const double effective_radius,
                                     const double effective_modulus)
      : R(effective_radius)
      , E(effective_modulus)
      , n_H(4.0 / 3.0 * effective_modulus * std::sqrt(effective_radius))
      , sqrt_R(std::sqrt(effective_radius))
  {
  }

  RegisteredContactLaw
  NonlocalHertzLaw::registration()
  {
    RegisteredContactLaw r;
    r.name        = "nonlocal-hertz";
    r.description = "Gonzalez & Cuitino 2012, Eqs. 9-11, in Tatara's "
                    "configuration: each sphere held at its far pole";
    r.subsection  = "Nonlocal Hertz";
    r.make        = [](const LawParameterValues &, const ContactBodies &b) {
      return std::make_unique<NonlocalHertzLaw>(
        for_pair(b.R1, b.E1, b.nu1, b.R2, b.E2, b.nu2));
    };
    // gamma_NL is found self-consistently at every overlap of the pair.
    r.context = [](const LawParameterValues &, const ContactBodies &b) {
      return ContactContextAt([b](const double gamma) {
        ContactContext context;
        if (gamma > 0.0)
          context.nonlocal_overlap
            = solve_tatara_two_spheres(
                gamma, b.R1, b.E1, b.nu1, b.R2, b.E2, b.nu2)
                .nonlocal_overlap;
        return context;
      });
    };
    return r;
  }

  NonlocalHertzLaw
  NonlocalHertzLaw::for_pair(const double R1,
                             const double E1,
                             const double nu1,
                             const double R2,
                             const double E2,
                             const double nu2)
  {
    return NonlocalHertzLaw(dem::effective_radius(R1, R2),
                            dem::effective_modulus(E1, nu1, E2, nu2));
  }

  ContactResponse
  NonlocalHertzLaw::evaluate(const double gamma,
                             const ContactHistory &,
                             const ContactContext &context) const
  {
    return response(gamma, context.nonlocal_overlap);
  }

  ContactHistory
  NonlocalHertzLaw::updated_history(const double,
                                    const ContactHistory &history,
                                    const ContactContext &) const
  {
    return history;
  }

  // ---------------------------------------------------------------------
  // Closed configurations

  double
  nonlocal_scalar_root(const double       gamma,
                       const double       kappa,
                       const double       relative_tolerance,
                       const unsigned int max_iterations)
  {
    if (gamma <= 0.0)
      return 0.0;
    if (kappa == 0.0)
      return gamma;
    if (gamma > 4.0 / (27.0 * kappa * kappa))
      return -1.0;
    // g(s) = s - kappa s^{3/2} - gamma is concave with g(gamma) < 0: Newton
    // from the left increases monotonically towards the lower root.
    double s = gamma;
    for (unsigned int i = 0; i < max_iterations; ++i)
      {
        const double root  = std::sqrt(s);
        const double g     = s - kappa * s * root - gamma;
        const double slope = 1.0 - 1.5 * kappa * root;
        if (slope <= 0.0)
          break;
        const double step = -g / slope;
        s += step;
        if (std::abs(step) <= relative_tolerance * s)
          break;
      }
    return s;
  }

  TataraSolution
  solve_tatara_two_spheres(const double gamma,
                           const double R1,
                           const double E1,
                           const double nu1,
                           const double R2,
                           const double E2,
                           const double nu2)
  {
    TataraSolution sol;
    sol.n_H = 4.0 / 3.0 * effective_modulus(E1, nu1, E2, nu2)
              * std::sqrt(effective_radius(R1, R2));
    const double inverse_n_NL = nonlocal_compliance(pi, R1, E1, nu1)
                                + nonlocal_compliance(pi, R2, E2, nu2);
    sol.n_NL       = 1.0 / inverse_n_NL;
    const double s = nonlocal_scalar_root(gamma, sol.n_H * inverse_n_NL);
    if (s < 0.0)
      return sol;
    sol.force            = sol.n_H * s * std::sqrt(s);
    sol.nonlocal_overlap = sol.force * inverse_n_NL;
    sol.converged        = true;
    return sol;
  }

  ChainSolution
  solve_chain_between_plates(const unsigned int n_spheres,
                             const double       plate_approach,
                             const double       R,
                             const double       E,
                             const double       nu)
  {
    ChainSolution sol;
    const double  n_wall
      = 4.0 / 3.0 * effective_modulus(E, nu, rigid, 0.0) * std::sqrt(R);
    const double c       = nonlocal_compliance(pi, R, E, nu);
    const double gamma_w = plate_approach / (2.0 * n_spheres);
    const double s       = nonlocal_scalar_root(gamma_w, c * n_wall);
    sol.wall_overlap     = gamma_w;
    sol.sphere_overlap   = 2.0 * gamma_w;
    sol.hertz_force
      = gamma_w > 0.0 ? n_wall * gamma_w * std::sqrt(gamma_w) : 0.0;
    if (s < 0.0)
      return sol;
    sol.force                   = n_wall * s * std::sqrt(s);
    sol.wall_nonlocal_overlap   = c * sol.force;
    sol.sphere_nonlocal_overlap = 2.0 * c * sol.force;
    sol.converged               = true;
    return sol;
  }
} // namespace compax::dem

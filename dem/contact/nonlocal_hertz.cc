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
  // Contact network

  void
  NonlocalContactNetwork::clear()
  {
    n_H_.clear();
    offset_.assign(1, 0);
    other_.clear();
    compliance_.clear();
  }

  void
  NonlocalContactNetwork::reserve(const std::size_t n_contacts,
                                  const std::size_t n_incidences)
  {
    n_H_.reserve(n_contacts);
    offset_.reserve(n_contacts + 1);
    other_.reserve(n_incidences);
    compliance_.reserve(n_incidences);
  }

  std::size_t
  NonlocalContactNetwork::add_contact(const double n_H)
  {
    n_H_.push_back(n_H);
    offset_.push_back(other_.size());
    return n_H_.size() - 1;
  }

  void
  NonlocalContactNetwork::add_influence(const std::size_t other,
                                        const double      compliance)
  {
    other_.push_back(other);
    compliance_.push_back(compliance);
    ++offset_.back();
  }

  void
  NonlocalContactNetwork::add_incident(const std::size_t   other,
                                       const double        theta,
                                       const NonlocalBody &body)
  {
    const double c = nonlocal_compliance(theta,
                                         body.radius,
                                         body.youngs_modulus,
                                         body.poisson_ratio);
    if (c != 0.0)
      add_influence(other, c);
  }

  void
  NonlocalContactNetwork::build(const std::vector<NonlocalBody> &bodies,
                                const std::vector<Contact>      &contacts)
  {
    clear();
    const std::size_t n_bodies = bodies.size();

    // Contacts of each body, CSR by counting sort.
    particle_offset_.assign(n_bodies + 1, 0);
    for (const Contact &c : contacts)
      {
        ++particle_offset_[c.particle_i + 1];
        ++particle_offset_[c.particle_j + 1];
      }
    for (std::size_t p = 0; p < n_bodies; ++p)
      particle_offset_[p + 1] += particle_offset_[p];
    particle_contacts_.resize(particle_offset_[n_bodies]);
    for (std::size_t k = 0; k < contacts.size(); ++k)
      {
        particle_contacts_[particle_offset_[contacts[k].particle_i]++] = k;
        particle_contacts_[particle_offset_[contacts[k].particle_j]++] = k;
      }
    // The cursors now point at the next body's start: shift back.
    for (std::size_t p = n_bodies; p > 0; --p)
      particle_offset_[p] = particle_offset_[p - 1];
    particle_offset_[0] = 0;

    for (std::size_t k = 0; k < contacts.size(); ++k)
      {
        const Contact &c = contacts[k];
        add_contact(c.n_H);
        for (int side = 0; side < 2; ++side)
          {
            const std::size_t   p    = side == 0 ? c.particle_i : c.particle_j;
            const NonlocalBody &body = bodies[p];
            if (std::isinf(body.radius * body.youngs_modulus))
              continue;
            // Direction from the centre of p to the contact point.
            const double sign = side == 0 ? 1.0 : -1.0;
            for (std::size_t q = particle_offset_[p];
                 q < particle_offset_[p + 1];
                 ++q)
              {
                const std::size_t d = particle_contacts_[q];
                if (d == k)
                  continue;
                const double sign_d = contacts[d].particle_i == p ? 1.0 : -1.0;
                const double cos_theta
                  = std::clamp(sign * sign_d * c.normal.dot(contacts[d].normal),
                               -1.0,
                               1.0);
                add_incident(d, std::acos(cos_theta), body);
              }
          }
      }
  }

  // ---------------------------------------------------------------------
  // Algorithm 1

  NonlocalFixedPointResult
  solve_nonlocal_fixed_point(const NonlocalContactNetwork &network,
                             const std::vector<double>    &gamma,
                             std::vector<double>          &gamma_nl,
                             std::vector<double>          &force,
                             const double                  tolerance,
                             const unsigned int            max_iterations,
                             const bool                    warm_start)
  {
    const std::size_t n = network.n_contacts();
    if (!warm_start)
      gamma_nl.assign(n, 0.0);
    else
      gamma_nl.resize(n, 0.0);
    force.resize(n);

    const std::vector<std::size_t> &offset     = network.offset();
    const std::vector<std::size_t> &other      = network.other();
    const std::vector<double>      &compliance = network.compliance();

    const auto compute_forces = [&]() {
      for (std::size_t c = 0; c < n; ++c)
        {
          const double s = gamma[c] + gamma_nl[c];
          force[c]       = s > 0.0 ? network.n_H(c) * s * std::sqrt(s) : 0.0;
        }
    };

    NonlocalFixedPointResult result;
    while (result.iterations < max_iterations)
      {
        compute_forces();
        double change = 0.0;
        for (std::size_t c = 0; c < n; ++c)
          {
            double sum = 0.0;
            for (std::size_t q = offset[c]; q < offset[c + 1]; ++q)
              sum += compliance[q] * force[other[q]];
            // Written so that a NaN (a diverging iteration beyond the limit
            // point of Eq. 10) propagates instead of being skipped by max.
            const double step = std::abs(sum - gamma_nl[c]);
            if (!(step <= change))
              change = step;
            gamma_nl[c] = sum;
          }
        ++result.iterations;
        result.change = change;
        if (!std::isfinite(change))
          break;
        if (change < tolerance)
          {
            result.converged = true;
            break;
          }
      }
    compute_forces();
    return result;
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

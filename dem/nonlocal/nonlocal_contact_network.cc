#include "dem/nonlocal/nonlocal_contact_network.h"

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  void
  NonlocalContactNetwork::clear()
  {
    law_.clear();
    offset_.assign(1, 0);
    other_.clear();
    compliance_.clear();
  }

  void
  NonlocalContactNetwork::reserve(const std::size_t n_contacts,
                                  const std::size_t n_incidences)
  {
    law_.reserve(n_contacts);
    offset_.reserve(n_contacts + 1);
    other_.reserve(n_incidences);
    compliance_.reserve(n_incidences);
  }

  std::size_t
  NonlocalContactNetwork::add_contact(const ParticleLaw &law)
  {
    law_.push_back(&law);
    offset_.push_back(other_.size());
    return law_.size() - 1;
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
        add_contact(*c.law);
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
          force[c]       = law_response(network.law(c), s, {}).force;
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

} // namespace compax::dem

#include "dem/crystals/crystal_contacts.h"

#include "dem/contact/hertz.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// Angle [rad] between two vectors, robust near 0 and pi.
    double
    angle_between(const Eigen::Vector3d &a, const Eigen::Vector3d &b)
    {
      return std::atan2(a.cross(b).norm(), a.dot(b));
    }
  } // namespace

  CrystalContacts::CrystalContacts(const CrystalLattice        &lattice,
                                   const CrystalMaterial       &material,
                                   const CrystalFormulation     formulation,
                                   const CrystalContactOptions &options)
      : crystal(lattice)
      , material(material)
      , formulation(formulation)
      , options(options)
      , law(HertzLaw::for_pair(material.radius,
                               material.youngs_modulus,
                               material.poisson_ratio,
                               material.radius,
                               material.youngs_modulus,
                               material.poisson_ratio))
  {
    if (!(material.radius > 0.0) || !(material.youngs_modulus > 0.0)
        || !(material.poisson_ratio > -1.0 && material.poisson_ratio < 0.5))
      throw std::invalid_argument(
        "CrystalContacts: needs R > 0, E > 0 and -1 < nu < 0.5");
    if (std::abs(lattice.radius - material.radius) > 1e-12 * material.radius)
      throw std::invalid_argument(
        "CrystalContacts: lattice and material radii differ");
    // Candidates: lattice vectors in range, except multiples k d (k > 1)
    // of a shorter one, whose sphere is hidden behind the one at d.
    for (const Eigen::Vector3d &d : lattice.lattice_vectors(
           options.neighbour_range * 2.0 * material.radius))
      {
        bool hidden = false;
        for (const Eigen::Vector3d &e : reference)
          hidden = hidden
                   || (e.cross(d).norm() <= 1e-9 * e.norm() * d.norm()
                       && e.dot(d) > 0.0);
        if (!hidden)
          reference.push_back(d);
      }
    const std::size_t n = reference.size();
    opposite.assign(n, n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if ((reference[i] + reference[j]).norm() < 1e-9 * material.radius)
          opposite[i] = j;
    for (std::size_t i = 0; i < n; ++i)
      if (opposite[i] == n)
        throw std::logic_error(
          "CrystalContacts: lattice is not centrosymmetric");
    deformed.resize(n);
    gamma.resize(n);
    gamma_nl.assign(n, 0.0);
    force.assign(n, 0.0);
    network.reserve(n,
                    formulation == CrystalFormulation::nonlocal ? 2 * n * n
                                                                : 0);
  }

  void
  CrystalContacts::build_network()
  {
    network.clear();
    const std::size_t n       = deformed.size();
    const bool        coupled = formulation == CrystalFormulation::nonlocal
                         && options.nonlocal_scale != 0.0;
    const double R = material.radius, E = material.youngs_modulus,
                 nu = material.poisson_ratio;
    for (std::size_t i = 0; i < n; ++i)
      {
        network.add_contact(law);
        if (!coupled)
          continue;
        for (std::size_t j = 0; j < n; ++j)
          {
            // Particle 0: the other contacts e_j != d_i.
            if (j != i)
              {
                const double theta = angle_between(deformed[i], deformed[j]);
                network.add_influence(j,
                                      options.nonlocal_scale
                                        * nonlocal_compliance(theta, R, E, nu));
              }
            // The neighbour at d_i: its contact with particle 0 is -d_i,
            // its others are e_j != -d_i.
            if (j != opposite[i])
              {
                const double theta = angle_between(-deformed[i], deformed[j]);
                network.add_influence(j,
                                      options.nonlocal_scale
                                        * nonlocal_compliance(theta, R, E, nu));
              }
          }
      }
  }

  CrystalResponse
  CrystalContacts::solve(const Eigen::Vector3d &strains)
  {
    const double      R = material.radius;
    const std::size_t n = reference.size();
    for (std::size_t i = 0; i < n; ++i)
      {
        deformed[i]
          = (Eigen::Vector3d::Ones() - strains).cwiseProduct(reference[i]);
        gamma[i] = 2.0 * R - deformed[i].norm();
      }
    build_network();

    // One sweep of Algorithm 1 per call, so that a diverging iteration (no
    // nonlocal solution) is caught before it overflows: beyond a limit
    // point the iterates grow without bound (P ~ gamma_NL^{3/2}), so a
    // nonlocal overlap beyond 100 diameters, or a non-finite one, means
    // there is no solution.
    CrystalResponse response;
    const double    tolerance = options.relative_tolerance * R;
    for (bool warm = false; response.iterations < options.max_iterations;
         warm      = true)
      {
             const NonlocalFixedPointResult r = solve_nonlocal_fixed_point(
          network, gamma, gamma_nl, force, tolerance, 1, warm);
             ++response.iterations;
             const bool bounded = std::all_of(gamma_nl.begin(),
                                         gamma_nl.end(),
                                         [R](const double g) {
                                           return std::abs(g) <= 200.0 * R;
                                         })
                                  && std::isfinite(r.change);
             if (!bounded)
          break;
        if (r.converged)
          {
                 response.converged = true;
                 break;
          }
      }

    response.relative_density = crystal.relative_density(strains);
    const double volume       = crystal.measure_per_particle(strains);
    for (std::size_t i = 0; i < n; ++i)
      if (force[i] > 0.0)
        {
          ++response.coordination;
          response.stress += force[i] / deformed[i].norm()
                             * (deformed[i] * deformed[i].transpose());
        }
    response.stress /= 2.0 * volume;
    // Force on a face = stress times the face of the conventional cell,
    // i.e. cell measure / edge normal to the face.
    const double cell = volume * crystal.particles_per_cell;
    for (unsigned int axis = 0; axis < 3; ++axis)
      response.face_force[axis]
        = crystal.spans(axis)
            ? response.stress(axis, axis) * cell
                / (crystal.cell_size[axis] * (1.0 - strains[axis]))
            : std::numeric_limits<double>::quiet_NaN();
    return response;
  }
} // namespace compax::dem

#pragma once

#include "dem/contact/nonlocal_hertz.h"
#include "dem/contact/particle_law.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

/**
 * @file
 * The nonlocal contact formulation of Gonzalez & Cuitino 2012 as a layer on
 * a local elastic law: the contact network of Algorithm 1, whose contacts
 * feel the deformation of their particles by the other contact forces
 * (Eq. 5), and its fixed point. Eq. (10) is the layer on the Hertz law,
 * P = n_H (gamma + gamma_NL)^{3/2}; on another elastic law f it reads
 * P = f(gamma + gamma_NL): the nonlocal overlap shifts the local law's
 * argument, since Eq. (5) describes the sphere's far field whatever the law
 * of the contact zone.
 */

namespace compax::dem
{
  /**
   * Whether the nonlocal formulation can run on @p law: an elastic law,
   * one that keeps no internal variables, so that its force is a function
   * of the shifted overlap alone. A law with a history (plastic radius,
   * largest overlap) would need its history to follow the fixed point,
   * which Gonzalez & Cuitino 2012 do not define.
   */
  inline bool
  elastic_law(const ParticleLaw &law)
  {
    return history_variables(law).empty();
  }

  /**
   * The contact network of Algorithm 1 in flat (CSR) arrays: for each
   * contact c its local law and the list of the contacts
   * incident to it (sharing particle i or particle j) with the influence
   * coefficient w/P of Eq. (5) [m/N] that each of them exerts on c. The
   * arrays keep their capacity across clear(), so rebuilding the network at
   * each residual evaluation allocates nothing once warmed up.
   *
   * Two ways to fill it:
   * - streaming: add_contact(law), then add_incident() for every other
   *   contact on either of its particles, then the next contact;
   * - geometric: build(), from the contacts' particle indices, unit normals
   *   and the bodies' radii and elastic constants (angles computed here).
   * Influences of rigid bodies are zero and are not stored.
   *
   * The network refers to the laws, it does not copy them: a law passed in
   * must outlive every solve of the network.
   */
  class NonlocalContactNetwork
  {
  public:
    /// One contact for build(): particles i and j, the unit normal from i
    /// towards j, and the local law (elastic_law()). A wall is a body like
    /// any other (rigid radius and modulus); its normal points from i into
    /// the wall.
    struct Contact
    {
      std::size_t        particle_i;
      std::size_t        particle_j;
      Eigen::Vector3d    normal;
      const ParticleLaw *law;
    };

    /// Remove all contacts, keep the capacity.
    void
    clear();

    /// Reserve room for contacts and incidences (pairs of incident contacts).
    void
    reserve(std::size_t n_contacts, std::size_t n_incidences);

    /// Append a contact that follows the elastic law @p law (elastic_law());
    /// returns its index. The add_incident() calls that follow belong to it.
    std::size_t
    add_contact(const ParticleLaw &law);

    /// Contact `other` acts on a particle `body` shared with the contact
    /// added last, at angle theta [rad] from it.
    void
    add_incident(std::size_t other, double theta, const NonlocalBody &body);

    /// Same with a precomputed influence coefficient w/P [m/N].
    void
    add_influence(std::size_t other, double compliance);

    /**
     * Build the network of the given contacts between bodies (indices into
     * `bodies`). O(sum over particles of their contacts squared) =
     * O(n̄ N_c); uses internal scratch arrays that keep their capacity.
     */
    void
    build(const std::vector<NonlocalBody> &bodies,
          const std::vector<Contact>      &contacts);

    std::size_t
    n_contacts() const
    {
      return law_.size();
    }

    std::size_t
    n_incidences() const
    {
      return other_.size();
    }

    /// The local law of contact c.
    const ParticleLaw &
    law(std::size_t c) const
    {
      return *law_[c];
    }

    /// CSR arrays: the influences on contact c are entries
    /// offset()[c] .. offset()[c+1]-1 of other() and compliance().
    const std::vector<std::size_t> &
    offset() const
    {
      return offset_;
    }

    const std::vector<std::size_t> &
    other() const
    {
      return other_;
    }

    const std::vector<double> &
    compliance() const
    {
      return compliance_;
    }

  private:
    std::vector<const ParticleLaw *> law_;
    std::vector<std::size_t>         offset_{0};
    std::vector<std::size_t>         other_;
    std::vector<double>              compliance_;
    // Scratch for build(): contacts of each particle, CSR.
    std::vector<std::size_t> particle_offset_;
    std::vector<std::size_t> particle_contacts_;
  };

  /// Outcome of solve_nonlocal_fixed_point().
  struct NonlocalFixedPointResult
  {
    /// Sweeps performed.
    unsigned int iterations = 0;
    /// Whether the last sweep changed gamma_NL by less than the tolerance.
    bool converged = false;
    /// max_c |change of gamma_NL[c]| in the last sweep [m].
    double change = 0.0;
  };

  /**
   * Algorithm 1 of Gonzalez & Cuitino 2012: Jacobi fixed-point iteration of
   * the nonlocal overlaps. One sweep computes P[c] = f_c(gamma + gamma_NL),
   * f_c the local law of contact c (Eq. 10 for Hertz: n_H (gamma +
   * gamma_NL)_+^{3/2}), for all contacts from the current gamma_NL, then
   * gamma_NL[c] = sum over incident d of (w/P)_{cd} P[d]; it stops when
   * max_c |change| < tolerance [m] or after max_iterations sweeps. On return
   * `force` holds the forces of the final gamma_NL (Algorithm 1, line 25).
   * The result does not depend on the order of the contacts (Jacobi, not
   * Gauss-Seidel). O(N_c + n_incidences) per sweep, no allocation once
   * `gamma_nl` and `force` have the network's size.
   *
   * @param gamma     overlaps, one per contact [m]
   * @param gamma_nl  nonlocal overlaps [m]; resized to the network; the
   *                  starting guess when warm_start, else started from 0
   * @param force     contact forces [N]; resized to the network
   */
  NonlocalFixedPointResult
  solve_nonlocal_fixed_point(const NonlocalContactNetwork &network,
                             const std::vector<double>    &gamma,
                             std::vector<double>          &gamma_nl,
                             std::vector<double>          &force,
                             double                        tolerance,
                             unsigned int                  max_iterations,
                             bool                          warm_start = false);
} // namespace compax::dem

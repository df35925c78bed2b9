#pragma once

#include "dem/crystals/granular_crystal.h"
#include "dem/nonlocal/nonlocal_contact_network.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

/**
 * @file
 * Contact forces of a granular crystal under an affine cell deformation,
 * with Hertz theory or with the nonlocal contact formulation of Gonzalez &
 * Cuitino 2012 (Eqs. 5, 9, 10, Algorithm 1), and the macroscopic load and
 * lateral reactions they transmit.
 */

namespace compax::dem
{
  /// Hertz theory (independent contacts) or the nonlocal formulation.
  enum class CrystalFormulation
  {
    hertz,
    nonlocal
  };

  /// Elastic spheres of the crystal.
  struct CrystalMaterial
  {
    /// Radius R [m].
    double radius = 0.01;
    /// Young's modulus E [Pa].
    double youngs_modulus = 1.85e6;
    /// Poisson's ratio nu [-], in (-1, 0.5).
    double poisson_ratio = 0.46;
  };

  /// Settings of CrystalContacts.
  struct CrystalContactOptions
  {
    /// Multiplies every nonlocal influence of Eq. (5); 1 is the paper's
    /// formulation, 0 switches the nonlocal terms off (Hertz theory).
    double nonlocal_scale = 1.0;
    /// Candidate contacts: lattice vectors whose undeformed length is at
    /// most this many diameters 2R.
    double neighbour_range = 1.75;
    /// Algorithm 1 stops when no nonlocal overlap changes by more than
    /// this times R in a sweep.
    double relative_tolerance = 1e-13;
    /// Sweeps of Algorithm 1 before giving up (no nonlocal solution).
    unsigned int max_iterations = 20000;
  };

  /// Macroscopic response of the deformed crystal.
  struct CrystalResponse
  {
    /// Whether the contact forces were found (always for Hertz; for the
    /// nonlocal formulation, whether Algorithm 1 converged).
    bool converged = false;
    /// Sweeps of Algorithm 1.
    unsigned int iterations = 0;
    /**
     * Force [N] on the face of the deformed conventional cell normal to x,
     * y and z: the load is component z, the lateral reactions x and y.
     * NaN along axes outside the lattice.
     */
    Eigen::Vector3d face_force = Eigen::Vector3d::Zero();
    /**
     * Macroscopic stress sigma = 1/(2 V) sum over the neighbours d of one
     * particle of P_d d (x) d / |d|, V the volume (area, length) per
     * particle: Pa in 3-D, N/m in 2-D, N in 1-D; compression positive.
     */
    Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
    /// Neighbours of a particle with a positive contact force.
    unsigned int coordination = 0;
    /// Relative density of the deformed cell.
    double relative_density = 0.0;
  };

  /**
   * The contacts of one particle of a granular crystal and their forces
   * under an affine deformation diag(1 - eps) of the lattice.
   *
   * The candidate contacts are the lattice vectors d up to
   * neighbour_range * 2R (the edges of the simplicial complex of Sec. 2.3
   * incident to particle 0); their overlaps are gamma_d = 2R - |d'| for the
   * deformed vectors d'. By translation invariance, contact d of particle 0
   * stands for every contact of the crystal parallel to it, so Algorithm 1
   * over the crystal reduces to a network on these contacts alone: the
   * nonlocal overlap of contact d collects Eq. (5) from the other contacts
   * e != d of particle 0 at the angle between d' and e', and from those of
   * the neighbour at d, whose contacts are the same vectors e, e != -d, at
   * the angle between -d' and e'. The contact forces of the crystal are
   * thus exactly those of Algorithm 1 on the infinite lattice, solved by
   * compax::dem::solve_nonlocal_fixed_point from gamma_NL = 0.
   *
   * Contact onset. A candidate contact carries force when
   * gamma + gamma_NL > 0 (Algorithm 1, line 8), with gamma_NL = 0 under
   * Hertz. Under the nonlocal formulation this is where the surface of the
   * two spheres, displaced by the other contact forces (Eq. 5, evaluated
   * at the contact point), closes the remaining geometric gap -gamma; it
   * can precede the geometric contact |d'| = 2R (second contacts of the
   * BCC crystal) or never happen for touching neighbours when gamma_NL < 0
   * (the gap of the close-packed layer of compressible spheres).
   *
   * A lattice vector k d (k > 1) that continues a shorter candidate d is
   * no candidate: that sphere is hidden behind the one at d (the overlap
   * model would otherwise let it touch through it beyond 50% strain), and
   * no two candidates are at theta = 0, where Eq. (5) diverges.
   *
   * solve() allocates nothing once the network has been built for the
   * first time.
   */
  class CrystalContacts
  {
  public:
    CrystalContacts(const CrystalLattice        &lattice,
                    const CrystalMaterial       &material,
                    CrystalFormulation           formulation,
                    const CrystalContactOptions &options = {});

    /// Contact forces and macroscopic response at cell strains
    /// (eps_x, eps_y, eps_z), compressive positive.
    CrystalResponse
    solve(const Eigen::Vector3d &strains);

    /// Undeformed candidate contact vectors of particle 0 [m].
    const std::vector<Eigen::Vector3d> &
    neighbours() const
    {
      return reference;
    }

    /// After solve(): deformed vectors [m], overlaps gamma [m], nonlocal
    /// overlaps gamma_NL [m] and forces P [N] of the candidates.
    const std::vector<Eigen::Vector3d> &
    deformed_neighbours() const
    {
      return deformed;
    }

    const std::vector<double> &
    overlaps() const
    {
      return gamma;
    }

    const std::vector<double> &
    nonlocal_overlaps() const
    {
      return gamma_nl;
    }

    const std::vector<double> &
    forces() const
    {
      return force;
    }

    /// Whether candidate i carries a positive force after solve().
    bool
    active(std::size_t i) const
    {
      return force[i] > 0.0;
    }

    /// n_H of two spheres of the crystal (Eq. 9) [N/m^{3/2}].
    double
    hertz_coefficient() const
    {
      return std::get<HertzLaw>(law).coefficient();
    }

    const CrystalLattice &
    lattice() const
    {
      return crystal;
    }

  private:
    void
    build_network();

    CrystalLattice        crystal;
    CrystalMaterial       material;
    CrystalFormulation    formulation;
    CrystalContactOptions options;
    /// Hertz's law of two spheres of the crystal, the local law of every
    /// contact.
    ParticleLaw                  law;
    std::vector<Eigen::Vector3d> reference;
    /// Index of -d for every candidate d.
    std::vector<std::size_t>     opposite;
    std::vector<Eigen::Vector3d> deformed;
    std::vector<double>          gamma;
    std::vector<double>          gamma_nl;
    std::vector<double>          force;
    NonlocalContactNetwork       network;
  };
} // namespace compax::dem

#pragma once

#include "dem/neighbors/cell_grid.h"
#include "dem/nonlocal/nonlocal_contact_network.h"
#include "dem/nonlocal/nonlocal_walls.h"
#include "dem/nonlocal/square_die.h"
#include "dem/particles/particle_system.h"
#include "dem/periodic/periodic_pairs.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/equilibrium_system.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace compax::dem
{
  /// Elastic constants of one material of the bed.
  struct ElasticMaterial
  {
    /// Young's modulus E [Pa].
    double youngs_modulus;
    /// Poisson's ratio nu [-].
    double poisson_ratio;
  };

  /// Settings of a NonlocalBedSystem.
  struct NonlocalBedOptions
  {
    /// Nonlocal formulation (Gonzalez & Cuitino 2012, Eqs. 9, 10 and
    /// Algorithm 1); false gives the local law alone (gamma_NL = 0).
    bool nonlocal = true;
    /// Verlet skin of the candidate contacts, times the mean radius [-].
    double skin = 0.25;
    /// Algorithm 1 stops when no gamma_NL changes by more than this times
    /// the mean radius in a sweep [-].
    double fixed_point_tolerance = 1e-13;
    /// Sweeps of Algorithm 1 before the state counts as beyond the limit
    /// point of the formulation (no solution; the residual is then NaN).
    unsigned int max_fixed_point_iterations = 5000;
    /// Start Algorithm 1 from the gamma_NL of the previous evaluation
    /// (Newton iterates move little); false starts from gamma_NL = 0 as in
    /// the paper.
    bool warm_start = true;
    /// The local law of every contact, on which the nonlocal formulation
    /// is the layer: the laws of a ContactModel that chose an elastic
    /// registered law (elastic_law(); checked at construction,
    /// std::invalid_argument otherwise), its materials numbered as the
    /// bed's. Empty: Hertz's law of the ElasticMaterial constants (Eq. 9).
    /// The ElasticMaterial constants give the nonlocal terms (Eq. 5) in
    /// either case.
    std::optional<ContactModel> local_laws;
  };

  /**
   * Elastic frictionless spheres of several materials in a die (the
   * square die of SquareDie: four flat die walls and two punches; or the
   * cylindrical die of DieWalls, whose curved wall's normal turns with the
   * particle; any NonlocalWalls) as an EquilibriumSystem, with local elastic
   * contacts (Hertz, or the elastic law of NonlocalBedOptions::local_laws)
   * or with the nonlocal contact formulation of Gonzalez & Cuitino 2012 as a
   * layer on them. No friction.
   *
   * Contacts. The candidates are the pairs and particle-wall pairs closer
   * than the Verlet skin; the list is rebuilt when a particle moved farther
   * than half the skin or a wall moved. Every candidate is an edge of the
   * simplicial complex of Algorithm 1 (a candidate apart, gamma < 0, may
   * still be closed by its nonlocal term, Fig. 4 right).
   *
   * Residual. At each call the overlaps gamma_c and normals are evaluated,
   * the influence coefficients (Eq. 5 per unit force, for every pair of
   * contacts on a common deformable particle; walls are rigid) are
   * refreshed for the current angles, Algorithm 1 (solve_nonlocal_fixed_
   * point) finds gamma_NL, warm-started from the previous call, and
   * P_c = f_c(gamma_c + gamma_NL,c), f_c the contact's local law (Eq. 10:
   * n_H (gamma_c + gamma_NL,c)_+^{3/2} for Hertz), are assembled into
   * F = sum_c P_c d gamma_c / dx, the out-of-balance force with the sign
   * of an energy gradient (as ContactAssembler). Cost O(n̄ N_c) per sweep.
   * If Algorithm 1 does not converge (beyond the limit point of the
   * formulation) F is NaN, which the solvers reject.
   *
   * Stiffness. assemble() gives the approximate K: the local law's
   * stiffness f_c'(gamma + gamma_NL) at the nonlocal overlap (3/2 n_H
   * (gamma + gamma_NL)^{1/2} for Hertz) plus
   * the geometric terms, on the pair pattern, symmetric.
   * apply_jacobian() gives the exact product J v = dF/dx v, including
   * d gamma_NL/dx through the linearized fixed point
   * (I - D C) dP = D (d gamma + dC P), D = diag(dP/ds), C the influence
   * matrix, dC from the turning contact directions (pair normals, and the
   * normals of curved walls, dn = (I - e_r e_r^T)_xy v / r on the
   * cylinder). J is not sparse
   * ((I - D C)^{-1} couples every contact of a connected network) and,
   * through dC, not symmetric: the nonlocal forces do not derive from a
   * potential. (At frozen angles they do: with s = gamma + C P the
   * function Phi = sum_c U(s_c) - P.C P / 2, U' = P, has dPhi/dgamma = P
   * because C is symmetric; the turning of the contact directions adds
   * -P.dC P / 2 to dPhi/dx that F does not have.)
   *
   * Holds references to the particles and the die; the die may be moved
   * between solves (the candidate list is rebuilt when a wall moved).
   */
  class NonlocalBedSystem final : public EquilibriumSystem
  {
  public:
    NonlocalBedSystem(ParticleSystem                     &particles,
                      const std::vector<ElasticMaterial> &materials,
                      const SquareDie                    &die,
                      NonlocalBedOptions                  options = {});

    /// The cylindrical die of a Bed (walls indexed by Wall).
    NonlocalBedSystem(ParticleSystem                     &particles,
                      const std::vector<ElasticMaterial> &materials,
                      const DieWalls                     &die,
                      NonlocalBedOptions                  options = {});

    /**
     * Spheres in a periodic cell without walls (an RVE at a fixed lattice;
     * positions unwrapped): a pair may touch through a lattice image,
     * x_j - x_i + H n, each image its own contact. Every periodic direction
     * must be wider than 2 R_max plus the skin (PeriodicCellGrid). The
     * lattice may change between solves.
     */
    NonlocalBedSystem(ParticleSystem                     &particles,
                      const std::vector<ElasticMaterial> &materials,
                      const PeriodicCell                 &cell,
                      NonlocalBedOptions                  options = {});

    /// Any wall geometry.
    NonlocalBedSystem(ParticleSystem                     &particles,
                      const std::vector<ElasticMaterial> &materials,
                      std::unique_ptr<NonlocalWalls>      walls,
                      NonlocalBedOptions                  options = {});

    std::size_t
    n_particles() const override
    {
      return particles.size();
    }

    double
    mean_radius() const override
    {
      return r_mean;
    }

    double
    skin() const override
    {
      return skin_;
    }

    Eigen::Map<Eigen::VectorXd>
    coordinates() override
    {
      return particles.coordinates();
    }

    ContactSums
    residual(Eigen::VectorXd &F) override;

    ContactSums
    assemble(Eigen::VectorXd &F, BlockSparseMatrix &K) override;

    bool
    limit_closing(const Eigen::VectorXd &s,
                  Eigen::VectorXd       &factor) const override;

    /**
     * Jv = J v with the exact Jacobian J = dF/dx at the state of the last
     * residual() or assemble() call (which must have succeeded). With
     * turning = false the change of the influence coefficients with the
     * contact directions (dC) is left out: the rest, G^T (D^-1 - C)^-1 G
     * plus the geometric terms, is symmetric, the Hessian of Phi at frozen
     * angles (see above), and positive definite on the loaded directions
     * wherever Algorithm 1 contracts and the geometric terms are small.
     */
    void
    apply_jacobian(const Eigen::VectorXd &v,
                   Eigen::VectorXd       &Jv,
                   bool                   turning = true);

    /// The frozen-angle Jacobian (apply_jacobian with turning = false).
    bool
    apply_model_hessian(const Eigen::VectorXd &v, Eigen::VectorXd &Hv) override
    {
      apply_jacobian(v, Hv, false);
      return true;
    }

    /// The exact Jacobian, turning contact directions included.
    bool
    apply_exact_jacobian(const Eigen::VectorXd &v, Eigen::VectorXd &Jv) override
    {
      apply_jacobian(v, Jv, true);
      return true;
    }

    /// Switches the formulation (the warm start is reset).
    void
    set_nonlocal(bool nonlocal);

    const NonlocalBedOptions &
    options() const
    {
      return opts;
    }

    /// Sum of the normal forces on each wall at the last evaluation [N],
    /// indexed by SquareDie::Face (square die) or Wall (cylindrical die).
    const std::array<double, NonlocalWalls::max_walls> &
    wall_forces() const
    {
      return wall_force;
    }

    /// Love-Weber stress of the contact forces at the last evaluation,
    /// sigma = -(1/V) sum_c P_c d_c (x) n_c (d_c the branch vector, tension
    /// positive) over the cell volume V [Pa]; zero without a periodic cell.
    Eigen::Matrix3d
    stress() const;

    /// Algorithm 1 at the last evaluation.
    const NonlocalFixedPointResult &
    fixed_point() const
    {
      return fixed_point_;
    }

    /// Algorithm 1 sweeps summed over all evaluations.
    std::size_t
    total_sweeps() const
    {
      return total_sweeps_;
    }

    /// Candidate contacts (pairs, then walls of each particle, sorted).
    std::size_t
    n_candidates() const
    {
      return keys.size();
    }

    /// Influences (pairs of incident candidates) in the network.
    std::size_t
    n_incidences() const
    {
      return network.n_incidences();
    }

    /// Contacts carrying force at the last evaluation.
    std::size_t
    n_loaded() const
    {
      return n_loaded_;
    }

    /// Particle pairs (wall contacts not counted) carrying force at the
    /// last evaluation.
    std::size_t
    n_loaded_pairs() const
    {
      return n_loaded_pairs_;
    }

    /// Largest gamma_NL / gamma over loaded contacts at the last evaluation
    /// (0 for Hertz) [-].
    double
    max_nonlocal_ratio() const;

    /// Forces the candidate list to be rebuilt at the next evaluation.
    void
    invalidate()
    {
      dirty = true;
    }

  private:
    /// A candidate: particle i and particle j > i (through the lattice
    /// image `image` in a periodic cell), or wall j - N.
    struct Key
    {
      std::uint32_t i;
      std::uint32_t j;
      LatticeImage  image = {0, 0, 0};
    };

    /// An incidence of contacts c and d on the deformable particle p:
    /// u_c = sign_c n_c and u_d = sign_d n_d are the directions from p's
    /// centre to the two contact points.
    struct Incidence
    {
      std::uint32_t d;
      float         sign_c;
      float         sign_d;
      std::uint32_t body; // material of p
    };

    void
    update_list();

    void
    rebuild();

    /// Overlaps, normals, influences, Algorithm 1, forces; F and sums.
    ContactSums
    evaluate(Eigen::VectorXd &F);

    ParticleSystem                &particles;
    std::vector<ElasticMaterial>   materials;
    std::unique_ptr<NonlocalWalls> walls;
    const PeriodicCell            *cell = nullptr;
    Eigen::Matrix3d                reference_lattice;
    PeriodicCellGrid               periodic_grid;
    std::vector<ImagePair>         image_pairs;
    NonlocalBedOptions             opts;
    double                         r_mean = 0.0;
    double                         skin_  = 0.0;

    // Candidate list.
    bool                                         dirty    = true;
    std::uint64_t                                revision = 0;
    std::vector<Key>                             keys, old_keys;
    std::vector<ParticleLaw>                     laws;
    std::vector<Eigen::Vector3d>                 reference;
    std::array<double, NonlocalWalls::max_walls> reference_walls{};
    CellGrid                                     grid;
    std::vector<ParticlePair>                    candidate_pairs;
    std::vector<std::size_t>                     incidence_offset;
    std::vector<Incidence>                       incidences;
    std::vector<std::size_t> particle_offset, particle_contacts;

    // State of the last evaluation.
    std::vector<double>          gamma, distance, gamma_nl, old_gamma_nl, force;
    std::vector<double>          stiffness, dcompliance;
    std::vector<Eigen::Vector3d> normal;
    NonlocalContactNetwork       network;
    NonlocalFixedPointResult     fixed_point_;
    std::size_t                  total_sweeps_   = 0;
    std::size_t                  n_loaded_       = 0;
    std::size_t                  n_loaded_pairs_ = 0;
    std::array<double, NonlocalWalls::max_walls> wall_force{};

    // Stiffness pattern.
    std::uint64_t              pattern_revision = ~std::uint64_t(0);
    const BlockSparseMatrix   *pattern_matrix   = nullptr;
    std::vector<std::uint32_t> pair_slots;
    std::vector<ParticlePair>  pattern_pairs;

    // Scratch of apply_jacobian().
    std::vector<double>          a, y, y_new;
    std::vector<Eigen::Vector3d> dn;
  };
} // namespace compax::dem

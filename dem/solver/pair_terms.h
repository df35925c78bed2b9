#pragma once

#include "dem/contact/contact_response.h"
#include "dem/particles/particle_system.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_sums.h"
#include "dem/solver/history_update.h"
#include "dem/solver/pair_block.h"
#include "dem/solver/pair_pattern.h"
#include "dem/walls/die_walls.h"

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace compax::dem
{
  /**
   * Virgin contacts whose overlap is below this fraction of the centre
   * distance (of the radius, at a wall) are treated as touching without
   * force: such overlaps are round-off of the coordinates (a deposited bed
   * touches exactly), and their forces (~1e-12 N for R = 220 um) would
   * otherwise set the scale of the convergence test of an unloaded bed.
   */
  inline constexpr double touch_tolerance = 0.0;

  /// A wall contact's gap and the law's response there (all zero where
  /// the contact adds nothing), computed on any thread before one thread
  /// adds them in list order (add_wall_terms()).
  struct WallTerm
  {
    WallGap         gap;
    ContactResponse response;
  };

  /// The count of the contacts carrying a force and the sum of their |P|,
  /// from which ContactSums takes n_loaded and mean_force.
  struct LoadedContacts
  {
    std::size_t n       = 0;
    double      sum_abs = 0.0;

    void
    add(const ContactResponse &r)
    {
      if (r.force != 0.0)
        {
          ++n;
          sum_abs += std::abs(r.force);
        }
    }

    void
    add(const LoadedContacts &other)
    {
      n += other.n;
      sum_abs += other.sum_abs;
    }

    /// Sets sums.n_loaded and sums.mean_force.
    void
    report(ContactSums &sums) const
    {
      sums.n_loaded = n;
      if (n > 0)
        sums.mean_force = sum_abs / n;
    }
  };

  /// Particles per block of the count of loaded contacts. The pairs are
  /// counted block by block (a block: consecutive pairs whose particle i
  /// lies in the same block of particles) and the blocks summed in list
  /// order, so that the mean contact force does not depend on the number
  /// of threads, nor on listed pairs that carry nothing.
  inline constexpr std::uint32_t loaded_block_particles = 64;

  /// Whether pair b starts another block of the count than pair a before it.
  template <typename Pair>
  inline bool
  starts_loaded_block(const Pair &a, const Pair &b)
  {
    return a.i / loaded_block_particles != b.i / loaded_block_particles;
  }

  /**
   * Pair k of a bed (a die's Bed or a PeriodicBed): its unit normal n and
   * centre distance, and the law's response at overlap
   * gamma = R_i + R_j - |d| from `response(c, gamma)`, with the branch
   * vector d from branch_vector(bed, c). False where the pair adds
   * nothing: virgin and apart (most candidates of a Verlet list), or
   * neither force nor stiffness.
   */
  template <typename BedType, typename Response>
  inline bool
  pair_response(const BedType    &bed,
                const std::size_t k,
                const Response   &response,
                Eigen::Vector3d  &n,
                double           &dist,
                ContactResponse  &r)
  {
    const ParticleSystem &p = bed.particles;
    const auto           &c = bed.contacts.pairs[k];
    const Eigen::Vector3d d = branch_vector(bed, c);
    dist                    = d.norm();
    const double gamma      = p.radii[c.i] + p.radii[c.j] - dist;
    if (!has_history(c.history)
        && (gamma <= 0.0 || gamma < touch_tolerance * dist))
      return false;
    r = response(c, gamma);
    if (r.force == 0.0 && r.stiffness == 0.0)
      return false;
    n = d / dist;
    return true;
  }

  /**
   * Adds pair k of a bed to the residual F and, with stiffness, its
   * blocks to K at the slots of `pattern` (scatter_pair()).
   */
  template <bool with_stiffness, typename BedType, typename Response>
  inline void
  add_pair_terms(const BedType     &bed,
                 const std::size_t  k,
                 const Response    &response,
                 const PairPattern &pattern,
                 Eigen::VectorXd   &F,
                 BlockSparseMatrix *K,
                 LoadedContacts    &loaded)
  {
    Eigen::Vector3d n;
    double          dist;
    ContactResponse r;
    if (!pair_response(bed, k, response, n, dist, r))
      return;
    const auto &c = bed.contacts.pairs[k];
    scatter_pair(F,
                 with_stiffness ? K : nullptr,
                 c.i,
                 c.j,
                 with_stiffness ? pattern.ij(k) : 0,
                 with_stiffness ? pattern.ji(k) : 0,
                 n,
                 dist,
                 r);
    loaded.add(r);
  }

  /**
   * Pair k's force on its particle j, P n [N] (on i it is -P n), zero
   * where the pair adds nothing: the term scatter_pair() adds to F.
   */
  template <typename BedType, typename Response>
  inline Eigen::Vector3d
  pair_force_terms(const BedType    &bed,
                   const std::size_t k,
                   const Response   &response,
                   LoadedContacts   &loaded)
  {
    Eigen::Vector3d n;
    double          dist;
    ContactResponse r;
    if (!pair_response(bed, k, response, n, dist, r))
      return Eigen::Vector3d::Zero();
    loaded.add(r);
    return r.force * n;
  }
} // namespace compax::dem

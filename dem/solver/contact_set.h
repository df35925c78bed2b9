#pragma once

#include "dem/contact/particle_law.h"
#include "dem/neighbors/cell_grid.h"
#include "dem/particles/particle_system.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/verlet_list.h"
#include "dem/walls/die_walls.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace compax::dem
{
  /// A potential contact of particles i < j with its law and history.
  struct PairContact
  {
    std::uint32_t  i;
    std::uint32_t  j;
    ParticleLaw    law;
    ContactHistory history;
  };

  /// A pair contact's place in the sorted lists of a ContactSet: (i, j).
  inline ParticlePair
  pair_key(const PairContact &c)
  {
    return {c.i, c.j};
  }

  /// A potential contact of particle i with a rigid wall.
  struct WallContact
  {
    std::uint32_t  i;
    Wall           wall;
    ParticleLaw    law;
    ContactHistory history;
  };

  /// Overlap gamma = R_i + R_j - |x_i - x_j| of a pair contact [m].
  inline double
  pair_overlap(const ParticleSystem &p, const PairContact &c)
  {
    return p.radii[c.i] + p.radii[c.j]
           - (p.positions[c.i] - p.positions[c.j]).norm();
  }

  /// Overlap of a pair contact in a die [m] (the walls play no part).
  inline double
  contact_overlap(const ParticleSystem &p,
                  const DieWalls &,
                  const PairContact &c)
  {
    return pair_overlap(p, c);
  }

  /// Overlap of a particle with a wall [m].
  inline double
  contact_overlap(const ParticleSystem &p,
                  const DieWalls       &die,
                  const WallContact    &c)
  {
    return die.gap(c.wall, p.positions[c.i], p.radii[c.i]).overlap;
  }

  /**
   * The candidate contacts of a bed in a die, particle pairs and particles
   * at the walls, as a VerletList. The list is rebuilt only when some
   * particle moved more than half the skin, or a wall plus a particle more
   * than the skin, since the last build.
   */
  class ContactSet : public VerletList<ContactSet, DieWalls>
  {
  public:
    using VerletList::VerletList;

    /// The pairs of the residual and the stiffness: the candidates within
    /// the skin, and the pairs with a history that may still act.
    std::vector<PairContact> pairs;
    std::vector<WallContact> walls;
    /**
     * Dormant pairs: pairs with a history (a plastic radius, a largest
     * overlap) that had parted by more than the skin plus their law's
     * separation_reach() at the last build. Until the next build no
     * particle moves half a skin, so each carries exactly no force and no
     * stiffness, and the residual and the stiffness skip them. A build
     * gives a pair back to `pairs` with its history once it comes nearer.
     * Sorted by (i, j), like `pairs`.
     */
    std::vector<PairContact> dormant;

    /// Calls @p f on every pair the set keeps: `pairs`, then `dormant`.
    template <typename F>
    void
    for_each_kept_pair(F &&f) const
    {
      for (const PairContact &c : pairs)
        f(c);
      for (const PairContact &c : dormant)
        f(c);
    }

    /// VerletList::update_histories() of the pairs, dormant ones
    /// included, and of the walls.
    BondChanges
    update_histories(const ParticleSystem &particles,
                     const DieWalls       &die,
                     double                resolution = 0.0);

  private:
    friend VerletList;

    bool
    moved_too_far(const ParticleSystem &particles, const DieWalls &die) const;

    /// The pairs and the walls within the skin, in the lists.
    void
    find_contacts(const ParticleSystem &particles,
                  const DieWalls       &die,
                  const ContactModel   &model);

    /// A wall contact's place in the list: (particle, wall).
    using WallKey = std::pair<std::uint32_t, int>;

    CellGrid                  grid;
    std::vector<ParticlePair> candidates;
    std::vector<WallKey>      wall_candidates;
    std::vector<PairContact>  old_pairs;
    std::vector<PairContact>  old_dormant;
    std::vector<WallContact>  old_walls;
    /// The walls' coordinates at the last build [m].
    double reference_walls[n_walls] = {0.0, 0.0, 0.0};
  };
} // namespace compax::dem

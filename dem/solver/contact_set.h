#pragma once

#include "dem/contact/bonded_elastoplastic.h"
#include "dem/neighbors/cell_grid.h"
#include "dem/particles/particle_system.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/verlet_list.h"
#include "dem/walls/die_walls.h"

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /// A potential contact of particles i < j with its law and history.
  struct PairContact
  {
    std::uint32_t          i;
    std::uint32_t          j;
    BondedElastoplasticLaw law;
    ContactHistory         history;
  };

  /// A potential contact of particle i with a rigid wall.
  struct WallContact
  {
    std::uint32_t          i;
    Wall                   wall;
    BondedElastoplasticLaw law;
    ContactHistory         history;
  };

  /// Bonds created and broken by one history update (Eq. 13).
  struct BondChanges
  {
    std::size_t formed = 0;
    std::size_t broken = 0;
  };

  /**
   * The candidate contacts of a bed (a Verlet list with a skin) together
   * with their internal variables (a_p, a_B).
   *
   * The list is rebuilt only when some particle moved more than half the
   * skin, or a wall plus a particle more than the skin, since the last
   * build. A rebuild keeps the history of every surviving pair, and keeps
   * a pair that has left the list if it has a history (a_p > 0): plastic
   * deformation is permanent even when two particles separate.
   */
  class ContactSet : public VerletList
  {
  public:
    /// @param skin Verlet skin [m], e.g. 0.3 R
    explicit ContactSet(double skin = 0.0);

    std::vector<PairContact> pairs;
    std::vector<WallContact> walls;

    /// Rebuilds the list if the displacement criterion asks for it;
    /// returns whether it did.
    bool
    update(const ParticleSystem &particles,
           const DieWalls       &walls,
           const ContactModel   &model);

    /// Rebuilds the list unconditionally.
    void
    rebuild(const ParticleSystem &particles,
            const DieWalls       &walls,
            const ContactModel   &model);

    /// Applies Eq. (13) to every contact at the current (converged)
    /// positions, with forces resolved to `resolution` [N] (see
    /// update_history()); the only place where histories change.
    BondChanges
    update_histories(const ParticleSystem &particles,
                     const DieWalls       &walls,
                     double                resolution = 0.0);

  private:
    /// A wall contact's place in the list: (particle, wall).
    using WallKey = std::pair<std::uint32_t, int>;

    CellGrid                  grid;
    std::vector<ParticlePair> candidates;
    std::vector<WallKey>      wall_candidates;
    std::vector<PairContact>  old_pairs;
    std::vector<WallContact>  old_walls;
    double                    reference_walls[n_walls] = {0.0, 0.0, 0.0};
  };

  /**
   * Applies Eq. (13) to one contact at overlap gamma and counts the bond
   * it forms or breaks. A contact whose force |P| is not above
   * `resolution` [N] (the equilibrium solve's force resolution) keeps its
   * plastic radius: the solve determines no force there (an unjammed
   * region's exact equilibrium is force-free), so its left-over overlap
   * is not plastic deformation (Eq. 13 at the converged state, with the
   * forces the solve resolves). Breakage (a = 0) always applies.
   */
  void
  update_history(const BondedElastoplasticLaw &law,
                 double                        gamma,
                 ContactHistory               &history,
                 BondChanges                  &changes,
                 double                        resolution = 0.0);

  /// Overlap gamma = R_i + R_j - |x_i - x_j| of a pair contact [m].
  inline double
  pair_overlap(const ParticleSystem &p, const PairContact &c)
  {
    return p.radii[c.i] + p.radii[c.j]
           - (p.positions[c.i] - p.positions[c.j]).norm();
  }
} // namespace compax::dem

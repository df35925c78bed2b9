#pragma once

#include "dem/contact/bonded_elastoplastic.h"
#include "dem/particles/particle_system.h"
#include "dem/periodic/periodic_cell.h"
#include "dem/periodic/periodic_pairs.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/contact_set.h"

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /**
   * A potential contact of particle i with the periodic image n of particle
   * j (i < j), with its law and history. The image joins the unwrapped
   * positions, so it stays valid however far the particles travel.
   */
  struct PeriodicContact
  {
    std::uint32_t          i;
    std::uint32_t          j;
    LatticeImage           image;
    BondedElastoplasticLaw law;
    ContactHistory         history;
  };

  /// Branch vector d = x_i - (x_j + H n) of a periodic contact [m]; the
  /// normal n = d/|d| points from the image of j to i.
  inline Eigen::Vector3d
  branch_vector(const ParticleSystem  &p,
                const PeriodicCell    &cell,
                const PeriodicContact &c)
  {
    return p.positions[c.i] - p.positions[c.j] - cell.image_offset(c.image);
  }

  /**
   * The candidate contacts of a periodic cell (a Verlet list with a skin)
   * with their internal variables (a_p, a_B).
   *
   * The list is rebuilt when the particles' displacements relative to the
   * affine motion of the cell since the last build, plus the change of
   * the cell acting on the longest candidate branch, could have brought
   * two surfaces within the skin. A rebuild keeps the history of every
   * surviving (i, j, image) and keeps pairs with a history that left the
   * list, as the die's ContactSet does.
   */
  class PeriodicContactSet : public VerletList
  {
  public:
    /// @param skin Verlet skin [m], e.g. 0.3 R
    explicit PeriodicContactSet(double skin = 0.0);

    std::vector<PeriodicContact> pairs;

    /// Rebuilds the list if the displacement criterion asks for it;
    /// returns whether it did.
    bool
    update(const ParticleSystem &particles,
           const PeriodicCell   &cell,
           const ContactModel   &model);

    /// Rebuilds the list unconditionally.
    void
    rebuild(const ParticleSystem &particles,
            const PeriodicCell   &cell,
            const ContactModel   &model);

    /// Applies Eq. (13) to every contact at the current (converged)
    /// positions, with forces resolved to `resolution` [N] (see
    /// update_history()); the only place where histories change.
    BondChanges
    update_histories(const ParticleSystem &particles,
                     const PeriodicCell   &cell,
                     double                resolution = 0.0);

  private:
    PeriodicCellGrid             grid;
    std::vector<ImagePair>       candidates;
    std::vector<PeriodicContact> old_pairs;
    Eigen::Matrix3d              reference_lattice;
  };
} // namespace compax::dem

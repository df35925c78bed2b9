#pragma once

#include "dem/contact/particle_law.h"
#include "dem/particles/particle_system.h"
#include "dem/periodic/periodic_cell.h"
#include "dem/periodic/periodic_pairs.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/verlet_list.h"

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
    std::uint32_t  i;
    std::uint32_t  j;
    LatticeImage   image;
    ParticleLaw    law;
    ContactHistory history;
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

  /// Overlap gamma = R_i + R_j - |d| of a periodic contact [m].
  inline double
  contact_overlap(const ParticleSystem  &p,
                  const PeriodicCell    &cell,
                  const PeriodicContact &c)
  {
    return p.radii[c.i] + p.radii[c.j] - branch_vector(p, cell, c).norm();
  }

  /// Where a periodic contact stands at the current positions.
  struct PeriodicContactGeometry
  {
    /// Branch vector d = x_i - (x_j + H n) [m], its length [m] and the
    /// overlap gamma = R_i + R_j - |d| [m].
    Eigen::Vector3d branch;
    double          distance;
    double          overlap;
    /// False for a virgin contact (no internal variables) that is apart:
    /// no law gives it a force, as the assembler assumes (pair_terms.h). A
    /// contact with a history may act apart (a solid bridge, adhesion).
    bool may_act;
  };

  inline PeriodicContactGeometry
  contact_geometry(const ParticleSystem  &p,
                   const PeriodicCell    &cell,
                   const PeriodicContact &c)
  {
    PeriodicContactGeometry g;
    g.branch   = branch_vector(p, cell, c);
    g.distance = g.branch.norm();
    g.overlap  = p.radii[c.i] + p.radii[c.j] - g.distance;
    g.may_act  = g.overlap > 0.0 || has_history(c.history);
    return g;
  }

  /**
   * The candidate contacts of a periodic cell, pairs through lattice
   * images, as a VerletList. The list is rebuilt when the particles'
   * displacements relative to the affine motion of the cell since the last
   * build, plus the change of the cell acting on the longest candidate
   * branch, could have brought two surfaces within the skin. A rebuild
   * throws if the cell is narrower than the largest diameter plus the skin
   * (a particle would touch its own image).
   */
  class PeriodicContactSet : public VerletList<PeriodicContactSet, PeriodicCell>
  {
  public:
    using VerletList::VerletList;

    std::vector<PeriodicContact> pairs;

  private:
    friend VerletList;

    bool
    moved_too_far(const ParticleSystem &particles,
                  const PeriodicCell   &cell) const;

    void
    find_contacts(const ParticleSystem &particles,
                  const PeriodicCell   &cell,
                  const ContactModel   &model);

    PeriodicCellGrid             grid;
    std::vector<ImagePair>       candidates;
    std::vector<PeriodicContact> old_pairs;
    /// The lattice at the last build [m].
    Eigen::Matrix3d reference_lattice = Eigen::Matrix3d::Identity();
  };
} // namespace compax::dem

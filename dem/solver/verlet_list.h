#pragma once

#include "dem/contact/contact_response.h"
#include "dem/particles/particle_system.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /// Whether a contact keeps internal variables (plastic radius or bond).
  inline bool
  has_history(const ContactHistory &h)
  {
    return h.a_p > 0.0 || h.a_B > 0.0;
  }

  /**
   * The bookkeeping the die's ContactSet and the periodic cell's
   * PeriodicContactSet share as Verlet lists with a skin: the skin, the
   * particle positions at the last build (from which the displacement
   * criterion measures), and a revision number that stiffness patterns
   * compare. When a list is due for a rebuild is each set's own criterion.
   */
  class VerletList
  {
  public:
    /// @param skin Verlet skin [m], e.g. 0.3 R
    explicit VerletList(const double skin)
        : skin_(skin)
    {
    }

    double
    skin() const
    {
      return skin_;
    }

    void
    set_skin(const double skin)
    {
      skin_ = skin;
    }

    /// Increases at every rebuild (stiffness patterns compare it); unique
    /// across all lists, so that a restored copy never aliases a newer
    /// list.
    std::uint64_t
    revision() const
    {
      return revision_;
    }

  protected:
    /// Whether a rebuild is due whatever the displacements: the list was
    /// never built, or the number of particles changed.
    bool
    must_rebuild(const ParticleSystem &particles) const
    {
      return !built || reference_positions.size() != particles.size();
    }

    /// The particle positions at the last build [m].
    const std::vector<Eigen::Vector3d> &
    built_positions() const
    {
      return reference_positions;
    }

    /// Records a rebuild at the particles' current positions.
    void
    record_build(const ParticleSystem &particles);

  private:
    double                       skin_;
    std::uint64_t                revision_ = 0;
    bool                         built     = false;
    std::vector<Eigen::Vector3d> reference_positions;
  };

  /**
   * The rebuild of a Verlet list that keeps histories: merges the sorted
   * keys of the new candidates into `contacts`, the sorted contacts of
   * the last build. A candidate already listed keeps its contact (law and
   * internal variables), a new one is `make(key)`, and a contact that left
   * the candidates stays if it has a history: plastic deformation is
   * permanent even when two particles separate. `key(contact)` orders the
   * contacts as the candidates; `old` is scratch, kept to avoid
   * allocations.
   */
  template <typename Contact, typename Key, typename KeyOf, typename Make>
  void
  merge_candidates(const std::vector<Key> &candidates,
                   std::vector<Contact>   &contacts,
                   std::vector<Contact>   &old,
                   const KeyOf            &key,
                   const Make             &make)
  {
    old.swap(contacts);
    contacts.clear();
    contacts.reserve(candidates.size() + 16);
    std::size_t k = 0;
    for (const Key &candidate : candidates)
      {
        while (k < old.size() && key(old[k]) < candidate)
          {
            if (has_history(old[k].history))
              contacts.push_back(old[k]);
            ++k;
          }
        if (k < old.size() && key(old[k]) == candidate)
          contacts.push_back(old[k++]);
        else
          contacts.push_back(make(candidate));
      }
    for (; k < old.size(); ++k)
      if (has_history(old[k].history))
        contacts.push_back(old[k]);
  }
} // namespace compax::dem

#pragma once

#include "dem/particles/particle_system.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/history_update.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace compax::dem
{
  /// A new revision number for a rebuilt contact list, unique across all
  /// lists, so that a restored copy never aliases a newer list.
  std::uint64_t
  next_contact_list_revision();

  /**
   * The candidate contacts of a bed (a Verlet list with a skin) together
   * with their internal variables (a_p, a_B), as the die's ContactSet and
   * the periodic cell's PeriodicContactSet keep them. The list is rebuilt
   * when the particles, relative to `Boundary` (the die's walls, the
   * cell's lattice), could have moved two surfaces within the skin since
   * the last build; a rebuild keeps the history of every surviving
   * contact, and keeps a contact that has left the list if it has a
   * history: plastic deformation is permanent even when two particles
   * separate (the die's ContactSet keeps the far ones aside, dormant).
   *
   * `Set` derives from VerletList<Set, Boundary>, holds `pairs` and says
   * when the particles moved too far (moved_too_far()) and how the
   * candidates are found (find_contacts(), by merge_candidates()); the
   * overlap of a contact is contact_overlap(particles, boundary, contact).
   */
  template <typename Set, typename Boundary>
  class VerletList
  {
  public:
    /// @param skin Verlet skin [m], e.g. 0.3 R
    explicit VerletList(const double skin = 0.0)
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

    /// Increases at every rebuild (stiffness patterns compare it).
    std::uint64_t
    revision() const
    {
      return revision_;
    }

    /// Rebuilds the list if the displacement criterion asks for it;
    /// returns whether it did.
    bool
    update(const ParticleSystem &particles,
           const Boundary       &boundary,
           const ContactModel   &model)
    {
      const bool needed = !built
                          || reference_positions.size() != particles.size()
                          || set().moved_too_far(particles, boundary);
      if (needed)
        rebuild(particles, boundary, model);
      return needed;
    }

    /// Rebuilds the list unconditionally.
    void
    rebuild(const ParticleSystem &particles,
            const Boundary       &boundary,
            const ContactModel   &model)
    {
      set().find_contacts(particles, boundary, model);
      reference_positions = particles.positions;
      built               = true;
      revision_           = next_contact_list_revision();
    }

    /// Applies Eq. (13) to every pair contact at the current (converged)
    /// positions, with forces resolved to `resolution` [N] (see
    /// update_history()); the only place where histories change.
    BondChanges
    update_histories(const ParticleSystem &particles,
                     const Boundary       &boundary,
                     const double          resolution = 0.0)
    {
      BondChanges changes;
      update_histories_of(
        set().pairs, particles, boundary, resolution, changes);
      return changes;
    }

  protected:
    /// Eq. (13) on each of @p contacts (pairs, or a set's walls), counting
    /// the bonds formed and broken into @p changes.
    template <typename Contacts>
    static void
    update_histories_of(Contacts             &contacts,
                        const ParticleSystem &particles,
                        const Boundary       &boundary,
                        const double          resolution,
                        BondChanges          &changes)
    {
      for (auto &c : contacts)
        update_history(c.law,
                       contact_overlap(particles, boundary, c),
                       c.history,
                       changes,
                       resolution);
    }

    /// The particle positions at the last build [m].
    const std::vector<Eigen::Vector3d> &
    built_positions() const
    {
      return reference_positions;
    }

  private:
    Set &
    set()
    {
      return static_cast<Set &>(*this);
    }

    const Set &
    set() const
    {
      return static_cast<const Set &>(*this);
    }

    double                       skin_;
    std::uint64_t                revision_ = 0;
    bool                         built     = false;
    std::vector<Eigen::Vector3d> reference_positions;
  };

  /**
   * The rebuild of a list that keeps histories: merges the sorted keys of
   * the new candidates into `contacts`, the sorted contacts of the last
   * build, and `asleep`, the sorted contacts set aside then (disjoint from
   * `contacts`). A candidate already kept keeps its contact (law and
   * internal variables), a new one is `make(key)`, and a contact that left
   * the candidates stays if it has a history: in `contacts`, unless
   * `set_aside(contact)` takes it (and returns true). `key(contact)` orders
   * the contacts as the candidates; `old` is scratch, kept to avoid
   * allocations.
   */
  template <typename Contact,
            typename Key,
            typename KeyOf,
            typename Make,
            typename SetAside>
  void
  merge_candidates(const std::vector<Key>     &candidates,
                   std::vector<Contact>       &contacts,
                   std::vector<Contact>       &old,
                   const std::vector<Contact> &asleep,
                   const KeyOf                &key,
                   const Make                 &make,
                   const SetAside             &set_aside)
  {
    old.swap(contacts);
    contacts.clear();
    contacts.reserve(candidates.size() + 16);
    std::size_t k = 0, s = 0;
    // The next kept contact in key order, from either list, and its removal.
    const auto front = [&]() -> const Contact * {
      if (k < old.size()
          && (s == asleep.size() || key(old[k]) < key(asleep[s])))
        return &old[k];
      return s < asleep.size() ? &asleep[s] : nullptr;
    };
    const auto pop = [&](const Contact *c) {
      if (k < old.size() && c == &old[k])
        ++k;
      else
        ++s;
    };
    const auto keep_apart = [&](const Contact &c) {
      if (has_history(c.history) && !set_aside(c))
        contacts.push_back(c);
    };
    for (const Key &candidate : candidates)
      {
        const Contact *c = front();
        for (; c != nullptr && key(*c) < candidate; c = front())
          {
            keep_apart(*c);
            pop(c);
          }
        if (c != nullptr && key(*c) == candidate)
          {
            contacts.push_back(*c);
            pop(c);
          }
        else
          contacts.push_back(make(candidate));
      }
    for (const Contact *c = front(); c != nullptr; c = front())
      {
        keep_apart(*c);
        pop(c);
      }
  }

  /// merge_candidates() of a list that sets nothing aside.
  template <typename Contact, typename Key, typename KeyOf, typename Make>
  void
  merge_candidates(const std::vector<Key> &candidates,
                   std::vector<Contact>   &contacts,
                   std::vector<Contact>   &old,
                   const KeyOf            &key,
                   const Make             &make)
  {
    merge_candidates(candidates,
                     contacts,
                     old,
                     std::vector<Contact>{},
                     key,
                     make,
                     [](const Contact &) { return false; });
  }
} // namespace compax::dem

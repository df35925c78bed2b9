#include "dem/solver/contact_set.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace compax::dem
{
  void
  update_history(const BondedElastoplasticLaw &law,
                 const double                  gamma,
                 ContactHistory               &history,
                 BondChanges                  &changes,
                 const double                  resolution)
  {
    if (resolution > 0.0)
      {
        const ContactResponse r = law.response(gamma, history.a_p, history.a_B);
        if (r.contact_radius > history.a_p && std::abs(r.force) <= resolution)
          return;
      }
    const ContactHistory next = law.updated_history(gamma, history);
    if (history.a_B == 0.0 && next.a_B > 0.0)
      ++changes.formed;
    else if (history.a_B > 0.0 && next.a_B == 0.0)
      ++changes.broken;
    history = next;
  }

  std::uint64_t
  next_contact_list_revision()
  {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
  }

  ContactSet::ContactSet(const double skin)
      : skin_(skin)
  {
  }

  bool
  ContactSet::update(const ParticleSystem &particles,
                     const DieWalls       &die,
                     const ContactModel   &model)
  {
    bool needed = !built || reference_positions.size() != particles.size();
    if (!needed)
      {
        double max_sq = 0.0;
        for (std::size_t i = 0; i < particles.size(); ++i)
          max_sq = std::max(
            max_sq,
            (particles.positions[i] - reference_positions[i]).squaredNorm());
        const double max_move  = std::sqrt(max_sq);
        double       wall_move = 0.0;
        for (int w = 0; w < n_walls; ++w)
          wall_move = std::max(wall_move,
                               std::abs(die.coordinate(static_cast<Wall>(w))
                                        - reference_walls[w]));
        needed = 2.0 * max_move >= skin_ || max_move + wall_move >= skin_;
      }
    if (needed)
      rebuild(particles, die, model);
    return needed;
  }

  void
  ContactSet::rebuild(const ParticleSystem &particles,
                      const DieWalls       &die,
                      const ContactModel   &model)
  {
    grid.find_pairs(particles.positions, particles.radii, skin_, candidates);

    // Merge the sorted candidates with the sorted old contacts.
    old_pairs.swap(pairs);
    pairs.clear();
    pairs.reserve(candidates.size() + 16);
    std::size_t k    = 0;
    auto        make = [&](const ParticlePair &ij) {
      const auto i = ij.first, j = ij.second;
      return PairContact{i,
                         j,
                         model.pair_law(particles.materials[i],
                                        particles.radii[i],
                                        particles.materials[j],
                                        particles.radii[j]),
                         ContactHistory{}};
    };
    for (const ParticlePair &ij : candidates)
      {
        while (k < old_pairs.size()
               && std::make_pair(old_pairs[k].i, old_pairs[k].j) < ij)
          {
            if (has_history(old_pairs[k].history))
              pairs.push_back(old_pairs[k]);
            ++k;
          }
        if (k < old_pairs.size() && old_pairs[k].i == ij.first
            && old_pairs[k].j == ij.second)
          pairs.push_back(old_pairs[k++]);
        else
          pairs.push_back(make(ij));
      }
    for (; k < old_pairs.size(); ++k)
      if (has_history(old_pairs[k].history))
        pairs.push_back(old_pairs[k]);

    // Wall candidates, in order (i, wall), merged the same way.
    old_walls.swap(walls);
    walls.clear();
    k = 0;
    for (std::uint32_t i = 0; i < particles.size(); ++i)
      for (int w = 0; w < n_walls; ++w)
        {
          const Wall wall = static_cast<Wall>(w);
          auto       key  = std::make_pair(i, w);
          while (k < old_walls.size()
                 && std::make_pair(old_walls[k].i,
                                   static_cast<int>(old_walls[k].wall))
                      < key)
            {
              if (has_history(old_walls[k].history))
                walls.push_back(old_walls[k]);
              ++k;
            }
          const bool old_match = k < old_walls.size() && old_walls[k].i == i
                                 && old_walls[k].wall == wall;
          const double gap
            = -die.gap(wall, particles.positions[i], particles.radii[i])
                 .overlap;
          const bool near = gap < skin_;
          if (old_match)
            {
              if (near || has_history(old_walls[k].history))
                walls.push_back(old_walls[k]);
              ++k;
            }
          else if (near)
            walls.push_back(WallContact{i,
                                        wall,
                                        model.wall_law(particles.materials[i],
                                                       particles.radii[i]),
                                        ContactHistory{}});
        }
    for (; k < old_walls.size(); ++k)
      if (has_history(old_walls[k].history))
        walls.push_back(old_walls[k]);

    reference_positions = particles.positions;
    for (int w = 0; w < n_walls; ++w)
      reference_walls[w] = die.coordinate(static_cast<Wall>(w));
    built     = true;
    revision_ = next_contact_list_revision();
  }

  BondChanges
  ContactSet::update_histories(const ParticleSystem &particles,
                               const DieWalls       &die,
                               const double          resolution)
  {
    BondChanges changes;
    for (PairContact &c : pairs)
      update_history(
        c.law, pair_overlap(particles, c), c.history, changes, resolution);
    for (WallContact &c : walls)
      update_history(
        c.law,
        die.gap(c.wall, particles.positions[c.i], particles.radii[c.i]).overlap,
        c.history,
        changes,
        resolution);
    return changes;
  }
} // namespace compax::dem

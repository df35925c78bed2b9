#include "dem/solver/contact_set.h"

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  bool
  ContactSet::moved_too_far(const ParticleSystem &particles,
                            const DieWalls       &die) const
  {
    const std::vector<Eigen::Vector3d> &x0     = built_positions();
    double                              max_sq = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i)
      max_sq = std::max(max_sq, (particles.positions[i] - x0[i]).squaredNorm());
    const double max_move  = std::sqrt(max_sq);
    double       wall_move = 0.0;
    for (int w = 0; w < n_walls; ++w)
      wall_move = std::max(wall_move,
                           std::abs(die.coordinate(static_cast<Wall>(w))
                                    - reference_walls[w]));
    return 2.0 * max_move >= skin() || max_move + wall_move >= skin();
  }

  void
  ContactSet::find_contacts(const ParticleSystem &particles,
                            const DieWalls       &die,
                            const ContactModel   &model)
  {
    grid.find_pairs(particles.positions, particles.radii, skin(), candidates);
    merge_candidates(
      candidates,
      pairs,
      old_pairs,
      [](const PairContact &c) { return ParticlePair(c.i, c.j); },
      [&](const ParticlePair &ij) {
        const auto [i, j] = ij;
        return PairContact{i,
                           j,
                           model.pair_law(particles.materials[i],
                                          particles.radii[i],
                                          particles.materials[j],
                                          particles.radii[j]),
                           ContactHistory{}};
      });

    // The walls within the skin of each particle, in order (i, wall).
    wall_candidates.clear();
    for (std::uint32_t i = 0; i < particles.size(); ++i)
      for (int w = 0; w < n_walls; ++w)
        if (-die
               .gap(static_cast<Wall>(w),
                    particles.positions[i],
                    particles.radii[i])
               .overlap
            < skin())
          wall_candidates.emplace_back(i, w);
    merge_candidates(
      wall_candidates,
      walls,
      old_walls,
      [](const WallContact &c) {
        return WallKey(c.i, static_cast<int>(c.wall));
      },
      [&](const WallKey &iw) {
        const auto [i, w] = iw;
        return WallContact{i,
                           static_cast<Wall>(w),
                           model.wall_law(particles.materials[i],
                                          particles.radii[i]),
                           ContactHistory{}};
      });
    for (int w = 0; w < n_walls; ++w)
      reference_walls[w] = die.coordinate(static_cast<Wall>(w));
  }

  BondChanges
  ContactSet::update_histories(const ParticleSystem &particles,
                               const DieWalls       &die,
                               const double          resolution)
  {
    BondChanges changes
      = VerletList::update_histories(particles, die, resolution);
    update_histories_of(walls, particles, die, resolution, changes);
    return changes;
  }
} // namespace compax::dem

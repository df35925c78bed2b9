#include "dem/solver/contact_set.h"

#include "dem/parallel_particles.h"

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
    // Asked before every residual; a maximum is exact in any order.
    const auto n = static_cast<std::ptrdiff_t>(particles.size());
#pragma omp parallel for reduction(max : max_sq) if (n >= parallel_particles)
    for (std::ptrdiff_t i = 0; i < n; ++i)
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
    // A pair apart by more than the skin plus its reach stays beyond its
    // reach until the next build (moved_too_far()). The reach gets a
    // relative margin of 1e-6, far above the rounding of the law's own
    // test, so that a dormant pair's force would be exactly zero.
    old_dormant.swap(dormant);
    dormant.clear();
    const auto set_aside = [&](const PairContact &c) {
      const double reach = separation_reach(c.law, c.history) * (1.0 + 1e-6);
      if (!(-pair_overlap(particles, c) > skin() + reach))
        return false;
      dormant.push_back(c);
      return true;
    };
    merge_candidates(
      candidates,
      pairs,
      old_pairs,
      old_dormant,
      pair_key,
      [&](const ParticlePair &ij) {
        const auto [i, j] = ij;
        return PairContact{i,
                           j,
                           model.pair_law(particles.materials[i],
                                          particles.radii[i],
                                          particles.materials[j],
                                          particles.radii[j]),
                           ContactHistory{}};
      },
      set_aside);

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
    // Beyond its reach a bonded pair's bridge breaks (a = 0), as it would
    // in `pairs`.
    update_histories_of(dormant, particles, die, resolution, changes);
    update_histories_of(walls, particles, die, resolution, changes);
    return changes;
  }
} // namespace compax::dem

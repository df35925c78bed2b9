#include "dem/neighbors/cell_grid.h"
#include "dem/parallel_particles.h"
#include "dem/solver/contact_set.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <omp.h>

using namespace compax::dem;

namespace
{
  /// A random polydisperse bed in a box, with overlaps and gaps.
  void
  random_bed(ParticleSystem &p, std::size_t n, unsigned seed)
  {
    std::mt19937_64 rng(seed);
    auto            u = [&]() { return (rng() >> 11) * 0x1.0p-53; };
    for (std::size_t i = 0; i < n; ++i)
      p.add({4e-3 * u(), 3e-3 * u(), 2e-3 * u()}, 100e-6 + 150e-6 * u());
  }
} // namespace

TEST(NeighborsCellGrid, EqualsBruteForceOnRandomBed)
{
  ParticleSystem p;
  random_bed(p, 800, 7);
  CellGrid                  grid;
  std::vector<ParticlePair> pairs;
  for (const double margin : {0.0, 20e-6, 80e-6})
    {
      grid.find_pairs(p.positions, p.radii, margin, pairs);
      const auto reference = brute_force_pairs(p.positions, p.radii, margin);
      EXPECT_GT(reference.size(), 100u);
      EXPECT_EQ(pairs, reference) << "margin " << margin;
    }
}

/// Above parallel_particles the threads search ranges of
/// particles; the list is brute force's, sorted, on 1, 2 and 3 threads.
TEST(NeighborsCellGrid, ThreadedSearchEqualsBruteForceOnAnyNumberOfThreads)
{
  ParticleSystem p;
  random_bed(p, static_cast<std::size_t>(parallel_particles) + 500, 5);
  const double margin         = 20e-6;
  const auto   reference      = brute_force_pairs(p.positions, p.radii, margin);
  const int    threads_before = omp_get_max_threads();
  CellGrid     grid;
  std::vector<ParticlePair> pairs;
  for (const int threads : {1, 2, 3})
    {
      omp_set_num_threads(threads);
      grid.find_pairs(p.positions, p.radii, margin, pairs);
      EXPECT_EQ(pairs, reference) << threads << " threads";
    }
  omp_set_num_threads(threads_before);
  EXPECT_GT(reference.size(), p.size());
}

TEST(NeighborsContactSet, HistorySurvivesRebuildsAndSeparation)
{
  ParticleSystem p;
  random_bed(p, 300, 11);
  DieWalls walls;
  walls.diameter           = 20e-3; // far away
  walls.lower_punch        = -1.0;
  walls.upper_punch        = 1.0;
  const ContactModel model = compax::testing::material1::contact_model();
  ContactSet         set(30e-6);
  set.rebuild(p, walls, model);
  ASSERT_GT(set.pairs.size(), 10u);
  // Mark every pair's history with its indices.
  for (auto &c : set.pairs)
    c.history[BondedElastoplasticLaw::a_p_slot] = 1e-9 * (1 + c.i * 1000 + c.j);
  const auto first = set.pairs.front();
  const auto rev   = set.revision();
  EXPECT_FALSE(set.update(p, walls, model));
  EXPECT_EQ(set.revision(), rev);

  // Move particles by more than half the skin: rebuild.
  std::mt19937_64 rng(3);
  for (auto &x : p.positions)
    x += Eigen::Vector3d(20e-6 * ((rng() >> 11) * 0x1.0p-53 - 0.5), 0, 0);
  p.positions[first.i] += Eigen::Vector3d(0, 0, 5e-3); // separates far
  EXPECT_TRUE(set.update(p, walls, model));
  EXPECT_NE(set.revision(), rev);
  set.for_each_kept_pair([](const PairContact &c) {
    if (BondedElastoplasticLaw::a_p(c.history) > 0.0)
      {
        EXPECT_DOUBLE_EQ(BondedElastoplasticLaw::a_p(c.history),
                         1e-9 * (1 + c.i * 1000 + c.j));
      }
  });
  // The pair that separated by 5 mm is kept, dormant.
  const auto is_first
    = [&](const PairContact &c) { return c.i == first.i && c.j == first.j; };
  EXPECT_TRUE(std::any_of(set.dormant.begin(), set.dormant.end(), is_first));
  EXPECT_TRUE(std::none_of(set.pairs.begin(), set.pairs.end(), is_first));
  // Every current neighbour pair is in the list.
  const auto  reference = brute_force_pairs(p.positions, p.radii, 30e-6);
  std::size_t found     = 0;
  for (const auto &c : set.pairs)
    found += std::binary_search(reference.begin(),
                                reference.end(),
                                ParticlePair{c.i, c.j});
  EXPECT_EQ(found, reference.size());
}

// Dormant pairs of the die's contact list (ContactSet::dormant): a pair
// with a history that parted by more than the skin plus its law's
// separation_reach() leaves the residual, and must change nothing. Checked
// against the laws' own responses (zero beyond the reach, non-zero just
// inside it), against Eq. (13) at a = 0 (the bridge breaks), and against
// the residual and the stiffness of the same bed with every pair active,
// which must agree to the bit, also on two threads.

#include "dem/contact/walton_braun.h"
#include "dem/die/die_analysis.h"
#include "dem/solver/contact_assembler.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/pressed_lattice.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

namespace
{
  /// The bed with its dormant pairs moved back among the active ones.
  Bed
  all_pairs_active(Bed bed)
  {
    auto &pairs = bed.contacts.pairs;
    pairs.insert(pairs.end(),
                 bed.contacts.dormant.begin(),
                 bed.contacts.dormant.end());
    bed.contacts.dormant.clear();
    std::sort(pairs.begin(),
              pairs.end(),
              [](const PairContact &a, const PairContact &b) {
                return pair_key(a) < pair_key(b);
              });
    return bed;
  }
} // namespace

/// Beyond its reach a law gives exactly no force and no stiffness, and just
/// inside it a bonded contact still acts: the reach is the tightest bound.
TEST(DormantContacts, LawsCarryNothingBeyondTheirReach)
{
  const ContactModel model = material1::contact_model();
  const double       R     = material1::R;
  const ParticleLaw  law   = model.pair_law(0, R, 0, R);
  const auto        &b     = bonded_law(law);
  // Loaded to overlaps below about 1e-7 m, elastic recovery outweighs the
  // plastic overlap and a contact acts apart (reach > 0); loaded further,
  // its contact radius closes before it parts (reach = 0).
  int acting_apart = 0, parting_in_contact = 0;
  for (const double gamma_max : {1e-11, 1e-9, 2e-8, 2e-7, 1e-6, 1e-5})
    for (const bool bridge : {true, false})
      {
        const double         a_p = b.plastic_radius(gamma_max);
        const ContactHistory h
          = BondedElastoplasticLaw::history(a_p, bridge ? a_p : 0.0);
        const double reach = separation_reach(law, h);
        EXPECT_EQ(reach, std::max(-b.breakage_overlap(a_p), 0.0));
        for (const double beyond :
             {reach * (1.0 + 1e-6) + 1e-15, 1.5 * reach + 1e-9, reach + R})
          {
            const ContactResponse r = law_response(law, -beyond, h);
            EXPECT_EQ(r.force, 0.0) << "gamma_max " << gamma_max;
            EXPECT_EQ(r.stiffness, 0.0) << "gamma_max " << gamma_max;
          }
        if (reach > 0.0)
          {
            ++acting_apart;
            EXPECT_NE(law_response(law, -(1.0 - 1e-3) * reach, h).force, 0.0)
              << "gamma_max " << gamma_max << ", bridge " << bridge;
          }
        else
          ++parting_in_contact;
      }
  EXPECT_EQ(acting_apart, 6);
  EXPECT_EQ(parting_in_contact, 6);
  EXPECT_EQ(separation_reach(law, ContactHistory{}), 0.0);

  // Walton-Braun with adhesion: the adhesive branch ends at contact.
  WaltonBraunLaw::Parameters p;
  p.loading_stiffness         = 1e4;
  p.unloading_stiffness_ratio = 5.0;
  p.adhesion_stiffness_ratio  = 0.5;
  p.plasticity_depth          = 0.1;
  const WaltonBraunLaw wb     = WaltonBraunLaw::for_pair(2e-4, 2e-4, p);
  const ContactHistory loaded = WaltonBraunLaw::history(1e-5);
  EXPECT_EQ(wb.separation_reach(loaded, {}), 0.0);
  EXPECT_LT(wb.evaluate(1e-9, loaded).force, 0.0);
  EXPECT_EQ(wb.evaluate(-1e-9, loaded).force, 0.0);
  EXPECT_EQ(wb.evaluate(-1e-9, loaded).stiffness, 0.0);
}

/// Two bonded spheres pulled apart: within the skin plus the reach the pair
/// stays active, beyond it dormant with its history; Eq. (13) there breaks
/// the bridge (a = 0) and keeps a_p, and the pair comes back with a_p when
/// the spheres touch again.
TEST(DormantContacts, APartedPairSleepsAndWakesWithItsHistory)
{
  const ContactModel model = material1::contact_model();
  // Loaded to 1 nm: the contact still acts apart (reach 1.8 nm).
  const double R = material1::R, skin = 0.3 * R, gamma = 1e-9;
  Bed          bed;
  bed.walls.diameter    = 40 * R;
  bed.walls.lower_punch = 0.0;
  bed.walls.upper_punch = 10 * R;
  bed.particles.add({0.0, 0.0, 5 * R}, R);
  bed.particles.add({2 * R - gamma, 0.0, 5 * R}, R);
  bed.contacts = ContactSet(skin);
  bed.contacts.rebuild(bed.particles, bed.walls, model);
  ASSERT_EQ(bed.contacts.pairs.size(), 1u);
  PairContact &pair  = bed.contacts.pairs.front();
  const double a_p   = bonded_law(pair.law).plastic_radius(gamma);
  pair.history       = BondedElastoplasticLaw::history(a_p, a_p);
  const double reach = separation_reach(pair.law, pair.history);
  ASSERT_GT(reach, 0.0);

  const auto place_at = [&](const double separation) {
    bed.particles.positions[1] = {2 * R + separation, 0.0, 5 * R};
    bed.contacts.rebuild(bed.particles, bed.walls, model);
  };
  place_at(skin + 0.5 * reach);
  ASSERT_EQ(bed.contacts.pairs.size(), 1u);
  EXPECT_TRUE(bed.contacts.dormant.empty());

  place_at(skin + 2.0 * reach);
  EXPECT_TRUE(bed.contacts.pairs.empty());
  ASSERT_EQ(bed.contacts.dormant.size(), 1u);
  EXPECT_EQ(bed.contacts.dormant.front().history,
            BondedElastoplasticLaw::history(a_p, a_p));
  EXPECT_EQ(measure(bed).n_bonds, 1u);

  const BondChanges changes
    = bed.contacts.update_histories(bed.particles, bed.walls);
  EXPECT_EQ(changes.broken, 1u);
  EXPECT_EQ(bed.contacts.dormant.front().history,
            BondedElastoplasticLaw::history(a_p, 0.0));
  EXPECT_EQ(measure(bed).n_bonds, 0u);

  place_at(-gamma);
  ASSERT_EQ(bed.contacts.pairs.size(), 1u);
  EXPECT_TRUE(bed.contacts.dormant.empty());
  EXPECT_EQ(bed.contacts.pairs.front().history,
            BondedElastoplasticLaw::history(a_p, 0.0));
}

/// A bed whose bonded pairs were loaded plastically and then spread apart:
/// its residual and stiffness with the far pairs dormant equal those with
/// every pair active to the bit, at the build and after moves of up to
/// half the skin (the most before the next build).
TEST(DormantContacts, DormantPairsChangeNeitherResidualNorStiffness)
{
  const ContactModel model = material1::contact_model();
  const double       R     = material1::R;
  const double       a     = 2 * R * 0.96;
  Bed                bed;
  bed.walls.diameter    = 40 * R;
  bed.walls.lower_punch = 0.0;
  bed.walls.upper_punch = 20 * R;
  bed.contacts.set_skin(0.3 * R);
  std::mt19937_64 rng(7);
  auto            u = [&]() { return (rng() >> 11) * 0x1.0p-53 - 0.5; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        bed.particles.add({(i - 1.5) * a, (j - 1.5) * a, 2 * R + k * a},
                          R * (1.0 + 0.04 * u()));
  bed.contacts.rebuild(bed.particles, bed.walls, model);

  // Every touching pair loaded to its overlap, with a bridge.
  for (PairContact &c : bed.contacts.pairs)
    {
      const double gamma = pair_overlap(bed.particles, c);
      if (gamma > 0.0)
        {
          const double a_p = bonded_law(c.law).plastic_radius(gamma);
          c.history        = BondedElastoplasticLaw::history(a_p, a_p);
        }
    }
  // The layers pulled far beyond the skin, the spheres of a layer moved
  // at random by up to 0.05 R, so that some still touch.
  for (auto &x : bed.particles.positions)
    x = Eigen::Vector3d(x[0], x[1], 2 * R + 1.35 * (x[2] - 2 * R))
        + 0.1 * R * Eigen::Vector3d(u(), u(), u());
  bed.contacts.rebuild(bed.particles, bed.walls, model);
  ASSERT_GE(bed.contacts.dormant.size(), 10u);
  std::size_t touching = 0, parted_active = 0;
  for (const PairContact &c : bed.contacts.pairs)
    {
      touching
        += law_response(c.law, pair_overlap(bed.particles, c), c.history).force
           != 0.0;
      parted_active += has_history(c.history);
    }
  ASSERT_GE(touching, 3u);
  ASSERT_GT(parted_active, touching);

  ContactAssembler                   assembler;
  const std::vector<Eigen::Vector3d> built = bed.particles.positions;
  for (int move = 0; move < 3; ++move)
    {
      for (std::size_t i = 0; move > 0 && i < built.size(); ++i)
        bed.particles.positions[i]
          = built[i]
            + 0.49 * bed.contacts.skin()
                * Eigen::Vector3d(u(), u(), u()).normalized();
      Bed               reference = all_pairs_active(bed);
      BlockSparseMatrix K, K_reference;
      Eigen::VectorXd   F, F_reference;
      assembler.assemble(bed, model, F, K);
      assembler.assemble(reference, model, F_reference, K_reference);
      ASSERT_FALSE(bed.contacts.dormant.empty()) << "rebuilt at move " << move;
      EXPECT_TRUE((F.array() == F_reference.array()).all()) << "move " << move;
      EXPECT_GT(F.norm(), 0.0);
      const Eigen::MatrixXd Kd(K.to_sparse()),
        Kd_reference(K_reference.to_sparse());
      EXPECT_TRUE((Kd.array() == Kd_reference.array()).all())
        << "move " << move;
    }
}

/// On two threads, the residual of a bed is the same to the bit whether or
/// not its list also holds pairs that carry nothing (here one far, virgin
/// pair for each particle of the lower half): a thread sums the pairs of
/// its share of the particles, however many other pairs are listed.
TEST(DormantContacts, ThreadedResidualDoesNotDependOnPairsThatCarryNothing)
{
  const ContactModel model = material1::contact_model();
  const int          side  = 24;
  Bed bed = compax::testing::pressed_lattice(model, material1::R, side);
  ASSERT_GE(bed.contacts.pairs.size(), ContactAssembler::parallel_pairs);

  Bed                       padded = bed;
  std::vector<PairContact> &pairs  = padded.contacts.pairs;
  const auto                layer  = static_cast<std::uint32_t>(side * side);
  const std::size_t         half   = padded.particles.size() / 2;
  const ParticleLaw         law    = pairs.front().law;
  for (std::uint32_t i = 0; i < half; ++i)
    pairs.push_back({i, i + 2 * layer, law, ContactHistory{}});
  std::sort(pairs.begin(),
            pairs.end(),
            [](const PairContact &a, const PairContact &b) {
              return pair_key(a) < pair_key(b);
            });

  omp_set_num_threads(2);
  ContactAssembler assembler;
  Eigen::VectorXd  F, F_padded;
  assembler.residual(bed, model, F);
  assembler.residual(padded, model, F_padded);
  EXPECT_GT(F.norm(), 0.0);
  EXPECT_TRUE((F.array() == F_padded.array()).all());
}

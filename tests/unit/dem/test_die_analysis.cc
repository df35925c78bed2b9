// The bed measures of a die state against hand counts: the bonding surface
// of Gonzalez 2018 Sec. 5.6 counts the plastic radii of the contacts that
// touch, not those of pairs that have parted (their a_p stays as history).

#include "dem/die/die_analysis.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

TEST(DieAnalysis, BondingSurfaceCountsTheContactsThatTouch)
{
  const double R = material1::R, gamma = 1e-6;
  Bed          bed;
  bed.walls.diameter    = 40 * R;
  bed.walls.lower_punch = 0.0;
  bed.walls.upper_punch = 10 * R;
  bed.particles.add({0.0, 0.0, 5 * R}, R);
  bed.particles.add({2 * R - gamma, 0.0, 5 * R}, R); // overlaps particle 0
  bed.particles.add({-6 * R, 0.0, 5 * R}, R);        // 4 R from particle 0
  const ContactModel model = material1::contact_model();
  bed.contacts             = ContactSet(0.3 * R);
  bed.contacts.rebuild(bed.particles, bed.walls, model);
  ASSERT_EQ(bed.contacts.pairs.size(), 1u);

  // The touching pair on its plastic loading curve (a = a_p), and a pair
  // that was loaded to a larger a_p and has parted since.
  PairContact &touching   = bed.contacts.pairs.front();
  const auto  &law        = bonded_law(touching.law);
  const double a_p        = law.plastic_radius(gamma);
  touching.history        = BondedElastoplasticLaw::history(a_p, a_p);
  const double a_p_parted = 2.0 * a_p;
  bed.contacts.pairs.push_back(
    {0, 2, touching.law, BondedElastoplasticLaw::history(a_p_parted, 0.0)});

  const BedMeasures m = measure(bed);
  EXPECT_NEAR(m.bonding_surface,
              a_p * a_p / (3 * R * R),
              1e-12 * a_p * a_p / (R * R));
  EXPECT_EQ(m.n_bonds, 1u);
  EXPECT_EQ(m.n_compressive, 1u);

  // Brought back into contact on its own loading curve (a_p twice as large
  // is reached at four times the overlap), the parted pair counts again.
  bed.particles.positions[2] = {-(2 * R - 4 * gamma), 0.0, 5 * R};
  EXPECT_NEAR(measure(bed).bonding_surface,
              (a_p * a_p + a_p_parted * a_p_parted) / (3 * R * R),
              1e-12 * a_p * a_p / (R * R));
}

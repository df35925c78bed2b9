// The archives' columns of a contact's internal variables: the current
// layout is the ContactHistory slots themselves; an archive written before
// the laws declared their variables (columns a_p, a_B, delta_max) is read
// into the slots of each contact's law by the names the law declares.

#include "coupling/history_columns.h"
#include "dem/contact/walton_braun.h"
#include "tests/support/gonzalez_material1.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace compax;
namespace material1 = compax::testing::material1;

namespace
{
  const dem::ParticleLaw
    bonded(dem::BondedElastoplasticLaw::for_pair(material1::elastoplastic(),
                                                 material1::R,
                                                 material1::elastoplastic(),
                                                 material1::R,
                                                 material1::K_Ic,
                                                 0.1));

  dem::ParticleLaw
  walton_braun()
  {
    dem::WaltonBraunLaw::Parameters p;
    p.loading_stiffness = 1e4;
    return dem::WaltonBraunLaw::for_pair(1e-4, 1e-4, p);
  }
} // namespace

TEST(HistoryColumns, SlotsRoundTrip)
{
  const dem::ContactHistory h
    = dem::BondedElastoplasticLaw::history(1e-6, 2e-6);
  std::vector<double> row{7.0};
  coupling::append_history(row, h);
  ASSERT_EQ(row.size(), 1 + coupling::history_columns);
  EXPECT_EQ(coupling::history_from_columns(&row[1],
                                           coupling::history_columns,
                                           bonded),
            h);
}

TEST(HistoryColumns, LegacyColumnsGoToTheSlotsOfTheirNames)
{
  const double legacy[3] = {1e-6, 2e-6, 3e-6}; // a_p, a_B, delta_max
  const dem::ContactHistory b
    = coupling::history_from_columns(legacy, 3, bonded);
  EXPECT_EQ(dem::BondedElastoplasticLaw::a_p(b), 1e-6);
  EXPECT_EQ(dem::BondedElastoplasticLaw::a_B(b), 2e-6);
  const dem::ContactHistory w
    = coupling::history_from_columns(legacy, 3, walton_braun());
  EXPECT_EQ(dem::WaltonBraunLaw::delta_max(w), 3e-6);
  EXPECT_EQ(w[1], 0.0);
}

TEST(HistoryColumns, AnotherNumberOfColumnsIsRefused)
{
  const double columns[4] = {0, 0, 0, 0};
  EXPECT_THROW(coupling::history_from_columns(columns, 4, bonded),
               std::runtime_error);
  EXPECT_THROW(coupling::history_from_columns(columns, 1, bonded),
               std::runtime_error);
}

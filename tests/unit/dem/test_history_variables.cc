// The internal variables every contact law declares (ContactLaw::
// history_variables()) against what its updated_history() writes: along a
// load-unload-reload path a law keeps its history in the slots it
// declares, leaves the others at 0, and a law that declares variables
// changes them on plastic loading. The ParaView snapshot lists each
// declared variable as the per-particle largest value over its contacts.

#include "dem/contact/contact_law_registry.h"
#include "dem/contact/pair_properties.h"
#include "dem/contact/walton_braun.h"
#include "dem/io/particle_vtu.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/vtu_text.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <set>
#include <string>
#include <unistd.h>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

namespace
{
  /// Checks the declarations of @p law and its history along a path that
  /// loads to gamma_max, unloads to a third of it and reloads past it.
  void
  expect_declared_slots_only(const ContactLaw       &law,
                             const ContactContextAt &context,
                             const double            gamma_max)
  {
    const std::vector<HistoryVariable> declared = law.history_variables();
    ASSERT_LE(declared.size(), ContactHistory::capacity) << law.name();
    std::set<std::string> symbols, names;
    for (const HistoryVariable &v : declared)
      {
        EXPECT_TRUE(symbols.insert(v.symbol).second) << law.name();
        EXPECT_TRUE(names.insert(v.name).second) << law.name();
        EXPECT_GT(std::strlen(v.unit), 0u) << law.name() << ": " << v.name;
      }
    ContactHistory history;
    bool           changed = false;
    for (const double g : {0.5, 1.0, 0.3, 1.2})
      for (int k = 1; k <= 20; ++k)
        {
          const double         gamma = g * gamma_max * k / 20.0;
          const ContactContext c = context ? context(gamma) : ContactContext{};
          const ContactHistory next = law.updated_history(gamma, history, c);
          changed |= !(next == history);
          history = next;
          for (std::size_t s = declared.size(); s < ContactHistory::capacity;
               ++s)
            EXPECT_EQ(history[s], 0.0)
              << law.name() << " writes slot " << s << " it does not declare";
        }
    EXPECT_EQ(changed, !declared.empty()) << law.name();
  }
} // namespace

TEST(HistoryVariables, EveryLawKeepsItsHistoryInTheSlotsItDeclares)
{
  const ContactBodies wall{1e-4, 5e9, 0.25, rigid, rigid, 0.0};
  for (const RegisteredContactLaw &entry : registered_contact_laws())
    {
      LawParameterValues defaults;
      for (const LawParameter &p : entry.parameters)
        defaults.emplace(p.name, p.default_value);
      const std::unique_ptr<ContactLaw> law = entry.make(defaults, wall);
      expect_declared_slots_only(*law,
                                 entry.context ? entry.context(defaults, wall)
                                               : ContactContextAt{},
                                 1e-2 * wall.R1);
    }
  const BondedElastoplasticLaw bonded
    = BondedElastoplasticLaw::for_pair(material1::elastoplastic(),
                                       material1::R,
                                       material1::elastoplastic(),
                                       material1::R,
                                       material1::K_Ic,
                                       0.1);
  expect_declared_slots_only(bonded, {}, 1e-2 * material1::R);
}

TEST(HistoryVariables, SnapshotListsTheLargestDeclaredValueOfEachParticle)
{
  ParticleSystem particles;
  for (int k = 0; k < 3; ++k)
    particles.add({0, 0, 2e-4 * k}, 1e-4);
  WaltonBraunLaw::Parameters parameters;
  parameters.loading_stiffness = 1e4;
  const ParticleLaw     law(WaltonBraunLaw::for_pair(1e-4, 1e-4, parameters));
  ParticleSnapshot      snapshot(particles);
  const Eigen::Vector3d n(0, 0, -1);
  snapshot.add_contact(0, 1, n, 1.0, law, WaltonBraunLaw::history(2e-7));
  snapshot.add_contact(1, 2, n, 1.0, law, WaltonBraunLaw::history(5e-7));
  const auto file = std::filesystem::temp_directory_path()
                    / ("compax-history-" + std::to_string(::getpid()) + ".vtu");
  snapshot.write(file);
  const compax::testing::VtuText vtu(file);
  std::filesystem::remove(file);
  // Only the variable the law declares: delta_max, as max_largest_overlap.
  EXPECT_FALSE(vtu.has_array("max_plastic_radius"));
  EXPECT_EQ(vtu.array("max_largest_overlap", 3),
            (std::vector<double>{2e-7, 5e-7, 5e-7}));
}

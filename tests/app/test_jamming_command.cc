// `compax jamming` through the real executable on a small bed: one row of
// jamming.csv per protocol and toughness; on the bonded path the unjammed
// relaxations lie below the jamming pressure and end for good once the bed
// has jammed; the frozen-history path has none; bad input names its entry.

#include "app_test_support.h"

using compax::testing::AppTest;
using compax::testing::Csv;

class JammingCommand : public AppTest
{
protected:
  /// 150 spheres in a 3 mm die, 20 steps to rho = 0.8, no branches.
  const std::string small_bed
    = "subsection Packing\n set Number of particles = 150\n"
      " set Die diameter = 3e-3\nend\n"
      "subsection Protocol\n set Final relative density = 0.8\n"
      " set Compaction steps = 20\n set Unloading points =\nend\n";
};

TEST_F(JammingCommand, SmallBedGivesOneFitPerProtocolAndToughness)
{
  write("small.prm",
        small_bed + "subsection Jamming\n set Material label = m1\nend\n");
  const auto r = compax("jamming small.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;

  const Csv jamming(folder / "out" / "jamming.csv");
  ASSERT_EQ(jamming.rows(), 4u);
  EXPECT_EQ(jamming.text.at("material")[0], "m1");
  EXPECT_EQ(jamming.text.at("protocol")[0], "bonded-path");
  EXPECT_EQ(jamming.text.at("protocol")[3], "frozen-history");
  EXPECT_EQ(jamming.text.at("contact_law")[0], "bonded-elastoplastic");
  EXPECT_EQ(jamming.column.at("fracture_toughness")[1], 0.0);
  for (std::size_t i = 0; i < 4; ++i)
    {
      EXPECT_GT(jamming.column.at("rho_jammed")[i], 0.4) << i;
      EXPECT_LE(jamming.column.at("rho_jammed")[i], 0.8) << i;
    }

  const Csv   path(folder / "out" / "jamming_path.csv");
  const auto &protocol  = path.text.at("protocol");
  const auto &relaxed   = path.column.at("relaxed");
  const auto &p         = path.column.at("upper_punch_pressure");
  const auto &step      = path.column.at("step");
  bool        jammed    = false;
  std::size_t n_relaxed = 0;
  for (std::size_t i = 0; i < path.rows(); ++i)
    {
      if (step[i] == 0)
        jammed = false; // the next case's deposit
      if (protocol[i] == "frozen-history")
        EXPECT_EQ(relaxed[i], 0.0) << "row " << i;
      else if (relaxed[i] == 1.0)
        {
          ++n_relaxed;
          EXPECT_FALSE(jammed) << "row " << i;
          EXPECT_LT(p[i], 0.5e6) << "row " << i; // the jamming pressure
        }
      else if (step[i] > 0 && !jammed)
        {
          // The first Newton state is where the case jammed.
          jammed          = true;
          const double K  = path.column.at("fracture_toughness")[i];
          bool         ok = false;
          for (std::size_t c = 0; c < 4; ++c)
            ok |= jamming.text.at("protocol")[c] == protocol[i]
                  && jamming.column.at("fracture_toughness")[c] == K
                  && jamming.column.at("rho_jammed")[c]
                       == path.column.at("relative_density")[i];
          EXPECT_TRUE(ok) << "row " << i;
        }
    }
  EXPECT_GT(n_relaxed, 0u);
  EXPECT_TRUE(std::filesystem::exists(folder / "out" / "timing.csv"));
}

/// A registered contact law is the law of every case (it once fell back to
/// the bonded law): the plastic-hardening law forms no bridges, so its one
/// case per protocol carries K_Ic = 0 and no state of its path has a bond
/// (the bonded law's jammed states of this bed hold about 500); jamming.csv
/// names the law.
TEST_F(JammingCommand, RegisteredLawIsTheLawOfEveryCase)
{
  write("plastic.prm",
        small_bed
          + "subsection Contact\n set Contact law = plastic-hardening\nend\n"
            "subsection Jamming\n set Protocols = bonded-path\nend\n");
  const auto r = compax("jamming plastic.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const Csv jamming(folder / "out" / "jamming.csv");
  ASSERT_EQ(jamming.rows(), 1u);
  EXPECT_EQ(jamming.column.at("fracture_toughness")[0], 0.0);
  EXPECT_EQ(jamming.text.at("contact_law")[0], "plastic-hardening");
  EXPECT_LE(jamming.column.at("rho_jammed")[0], 0.8);
  const Csv path(folder / "out" / "jamming_path.csv");
  ASSERT_GT(path.rows(), 20u);
  for (std::size_t i = 0; i < path.rows(); ++i)
    EXPECT_EQ(path.column.at("bonds")[i], 0.0) << "row " << i;
}

TEST_F(JammingCommand, ElasticSpheresAreRefusedByName)
{
  write("elastic.prm", "subsection Contact\n set Contact law = elastic\nend\n");
  expect_refused_without_output(compax("jamming elastic.prm -o out"),
                                {"Contact/Contact law"});
}

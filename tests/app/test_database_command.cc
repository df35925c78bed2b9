// `compax database` through the real executable on a small cell: the
// fitted cap passes through the compaction state it was fitted to (the
// yield function of the Drucker-Prager Cap, written out here, vanishes
// there), the shear line through the two shear failures, unloading ends
// at a vanishing axial stress, the table is one `compax tablet` accepts,
// and bad input is rejected. The radial-strain probes follow their
// prescribed strain ratios with the mass balance; a run stopped after a
// branch and resumed equals an uninterrupted one; validation.csv holds the
// fitted law's error on every path.
#include "app_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

using compax::testing::AppTest;
using compax::testing::Csv;

namespace
{
  const std::string small_database = "subsection Packing\n"
                                     " set Number of particles = 80\n"
                                     " set Seed = 5\n"
                                     "end\n"
                                     "subsection Paths\n"
                                     " set Final relative density = 0.76\n"
                                     " set Branch densities = 0.70, 0.76\n"
                                     " set Shear steps = 6\n"
                                     " set Radial steps = 3\n"
                                     "end\n"
                                     "subsection Validation\n"
                                     " set Held-out packing = false\n"
                                     "end\n";

  std::string
  read_text(const std::filesystem::path &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
} // namespace

using DatabaseCommand = AppTest;

TEST_F(DatabaseCommand, FittedCapPassesThroughTheCompactionStates)
{
  write("db.prm", small_database);
  const auto r = compax("database db.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv rows(folder / "out" / "database.csv");
  const Csv fit(folder / "out" / "dpc_table.csv");
  const Csv branches(folder / "out" / "branches.csv");
  ASSERT_EQ(fit.column.at("relative_density").size(), 2u);

  for (std::size_t b = 0; b < 2; ++b)
    {
      const double rho = fit.column.at("relative_density")[b];
      // The compaction row at the branch density.
      double p = 0.0, q = 0.0;
      bool   found = false;
      for (std::size_t k = 0; k < rows.column.at("branch").size(); ++k)
        if (rows.text.at("path")[k] == "compaction"
            && std::abs(rows.column.at("relative_density")[k] - rho) < 1e-9)
          {
            p     = rows.column.at("p")[k];
            q     = rows.column.at("q")[k];
            found = true;
          }
      ASSERT_TRUE(found) << "no compaction row at " << rho;
      const double d = fit.column.at("cohesion")[b];
      const double tb
        = std::tan(fit.column.at("friction_angle_deg")[b] * M_PI / 180.0);
      const double R = fit.column.at("cap_eccentricity")[b];
      // The cap belongs to the plastic density rho exp(-sum dp / K) (the
      // DPC's elastic volumetric strain along the compaction path, K from
      // the table's E and nu interpolated linearly, end rows held).
      const auto &T = fit.column;
      auto        K = [&](const double rho) {
        const auto &x = T.at("relative_density");
        std::size_t i = 0;
        while (i + 2 < x.size() && rho > x[i + 1])
          ++i;
        const double w = std::clamp((rho - x[i]) / (x[i + 1] - x[i]), 0.0, 1.0);
        const double E = (1 - w) * T.at("youngs_modulus")[i]
                         + w * T.at("youngs_modulus")[i + 1];
        const double nu = (1 - w) * T.at("poisson_ratio")[i]
                          + w * T.at("poisson_ratio")[i + 1];
        return E / (3 * (1 - 2 * nu));
      };
      double e = 0.0, p_old = 0.0, rho_old = 0.0;
      bool   first = true;
      for (std::size_t k = 0; k < rows.rows(); ++k)
        if (rows.text.at("path")[k] == "compaction"
            && rows.column.at("relative_density")[k] <= rho + 1e-12)
          {
            if (!first)
              e += (rows.column.at("p")[k] - p_old) / K(rho_old);
            first   = false;
            p_old   = rows.column.at("p")[k];
            rho_old = rows.column.at("relative_density")[k];
          }
      const double rho_p = branches.column.at("plastic_density")[b];
      EXPECT_NEAR(rho_p, rho * std::exp(-e), 1e-9);
      EXPECT_LT(rho_p, rho);
      // p_b at rho_p by the table's rule (log-linear, extrapolated).
      const auto &x  = T.at("relative_density");
      const auto &pt = T.at("cap_pressure");
      std::size_t i  = 0;
      while (i + 2 < x.size() && rho_p >= x[i + 1])
        ++i;
      const double w = (rho_p - x[i]) / (x[i + 1] - x[i]);
      const double pb
        = std::exp((1 - w) * std::log(pt[i]) + w * std::log(pt[i + 1]));
      EXPECT_NEAR(pb, branches.column.at("fitted_cap_pressure")[b], 1e-8 * pb);
      const double pa = (pb - R * d) / (1.0 + R * tb);
      // On the cap (F_c = 0) ...
      const double Fc = std::hypot(p - pa, R * q) - R * (d + pa * tb);
      EXPECT_NEAR(Fc, 0.0, 1e-8 * pb);
      // ... where the flow normal has the uniaxial-strain ratio 2/3.
      EXPECT_NEAR(R * R * q / (p - pa), 2.0 / 3.0, 1e-8);
      EXPECT_GT(fit.column.at("youngs_modulus")[b], 0.0);
      const double nu = fit.column.at("poisson_ratio")[b];
      EXPECT_TRUE(nu > -1.0 && nu < 0.5) << nu;

      // Unloading stops at the first state without axial compression.
      std::vector<double> sigma_zz;
      for (std::size_t k = 0; k < rows.column.at("branch").size(); ++k)
        if (rows.column.at("branch")[k] == double(b)
            && rows.text.at("path")[k] == "unloading")
          sigma_zz.push_back(rows.column.at("sigma_zz")[k]);
      ASSERT_FALSE(sigma_zz.empty());
      EXPECT_GE(sigma_zz.back(), 0.0);
      for (std::size_t k = 0; k + 1 < sigma_zz.size(); ++k)
        EXPECT_LT(sigma_zz[k], 0.0);
    }
  // The cap pressure grows with density.
  EXPECT_GT(fit.column.at("cap_pressure")[1], fit.column.at("cap_pressure")[0]);

  // The table drives the continuum tablet model.
  write("tablet.prm",
        "subsection Material\n set DPC table = out/dpc_table.csv\nend\n");
  const auto t = compax("tablet tablet.prm --check");
  EXPECT_EQ(t.exit_code, 0) << t.err;
}

TEST_F(DatabaseCommand, RejectsBranchDensitiesOutOfOrder)
{
  expect_prm_rejected(
    "database",
    "subsection Paths\n set Branch densities = 0.80, 0.75\nend\n",
    "Branch densities");
}

TEST_F(DatabaseCommand, RejectsBranchBeyondFinalDensity)
{
  expect_prm_rejected("database",
                      "subsection Paths\n set Final relative density = 0.8\n"
                      " set Branch densities = 0.70, 0.85\nend\n",
                      "Branch densities");
}

/// Every row's logarithmic strain satisfies the mass balance
/// rho = rho_0 exp(-tr eps); a radial probe keeps eps_xx = eps_yy =
/// k eps_zz in its increments from the loaded branch state and compresses
/// by the prescribed axial strain; validation.csv has a training or
/// held-out error for every path of the database.
TEST_F(DatabaseCommand, RadialProbesAndValidation)
{
  write("db.prm", small_database);
  const auto r = compax("database db.prm -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("path "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("held-out radial probes"), std::string::npos) << r.out;
  const Csv    rows(folder / "out" / "database.csv");
  const auto  &rho  = rows.column.at("relative_density");
  const auto  &path = rows.text.at("path");
  const double rho0 = rho.front();
  for (std::size_t k = 0; k < rows.rows(); ++k)
    {
      const double tr = rows.column.at("eps_xx")[k]
                        + rows.column.at("eps_yy")[k]
                        + rows.column.at("eps_zz")[k];
      EXPECT_NEAR(rho[k], rho0 * std::exp(-tr), 1e-9) << "row " << k;
    }
  std::map<std::string, int> radial_rows;
  for (const double ratio : {-0.5, 0.5, 1.0})
    {
      char name[32];
      std::snprintf(name, sizeof name, "radial_%.2f", ratio);
      for (const int b : {0, 1})
        {
          // The loaded state: the compaction row at the branch density.
          const double rho_b = Csv(folder / "out" / "branches.csv")
                                 .column.at("relative_density")[b];
          std::size_t start = rows.rows();
          for (std::size_t k = 0; k < rows.rows(); ++k)
            if (path[k] == "compaction" && std::abs(rho[k] - rho_b) < 1e-9)
              start = k;
          ASSERT_LT(start, rows.rows());
          std::vector<std::size_t> probe;
          for (std::size_t k = 0; k < rows.rows(); ++k)
            if (path[k] == name && rows.column.at("branch")[k] == b)
              probe.push_back(k);
          ASSERT_EQ(probe.size(), 3u) << name;
          radial_rows[name] += 3;
          for (std::size_t n = 0; n < probe.size(); ++n)
            {
              const std::size_t k = probe[n];
              auto              d = [&](const std::string &c) {
                return rows.column.at(c)[k] - rows.column.at(c)[start];
              };
              EXPECT_NEAR(d("eps_zz"), -0.02 * (n + 1) / 3.0, 1e-9);
              EXPECT_NEAR(d("eps_xx"), ratio * d("eps_zz"), 1e-9);
              EXPECT_NEAR(d("eps_yy"), ratio * d("eps_zz"), 1e-9);
            }
        }
    }

  const Csv v(folder / "out" / "validation.csv");
  ASSERT_GT(v.rows(), 0u);
  int held_out = 0, training = 0;
  for (std::size_t k = 0; k < v.rows(); ++k)
    {
      EXPECT_EQ(v.text.at("comparison")[k], "dpc_vs_rve");
      const bool radial = v.text.at("path")[k].rfind("radial_", 0) == 0;
      EXPECT_EQ(v.text.at("role")[k], radial ? "held_out" : "training");
      (radial ? held_out : training)++;
      const double e = v.column.at("stress_error")[k];
      EXPECT_TRUE(std::isfinite(e) && e >= 0.0) << v.text.at("path")[k];
    }
  // compaction + 2 x (unloading, shear, confinement, confined_shear) and
  // 2 x 3 radial probes.
  EXPECT_EQ(training, 9);
  EXPECT_EQ(held_out, 6);
}

/// Stopped after its first branch and resumed from the checkpoint, the run
/// writes exactly what an uninterrupted run writes.
TEST_F(DatabaseCommand, ResumedRunEqualsUninterrupted)
{
  write("db.prm", small_database);
  const auto whole = compax("database db.prm -o whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;

  write("stop.prm",
        small_database
          + "subsection Checkpoints\n set Stop after branches = 1\nend\n");
  const auto first = compax("database stop.prm -o first");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("Stopped as asked"), std::string::npos);
  ASSERT_TRUE(
    std::filesystem::exists(folder / "first" / "checkpoints" / "database.h5"));
  EXPECT_FALSE(std::filesystem::exists(folder / "first" / "dpc_table.csv"));
  const Csv partial(folder / "first" / "database.csv");
  for (const double b : partial.column.at("branch"))
    EXPECT_LE(b, 0.0);

  write("resume.prm",
        small_database
          + "subsection Checkpoints\n set Resume from = "
            "first/checkpoints/database.h5\nend\n");
  const auto second = compax("database resume.prm -o second");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.out.find("resumed after branch 1"), std::string::npos)
    << second.out;
  for (const char *file :
       {"database.csv", "branches.csv", "dpc_table.csv", "validation.csv"})
    {
      const std::string a = read_text(folder / "whole" / file);
      EXPECT_FALSE(a.empty()) << file;
      EXPECT_EQ(a, read_text(folder / "second" / file)) << file;
    }
}

TEST_F(DatabaseCommand, RejectsCheckpointOfAnotherStudy)
{
  write("db.prm",
        small_database
          + "subsection Checkpoints\n set Stop after branches = 1\nend\n");
  ASSERT_EQ(compax("database db.prm -o first").exit_code, 0);
  std::filesystem::rename(folder / "first" / "checkpoints" / "database.h5",
                          folder / "checkpoint.h5");
  std::filesystem::remove_all(folder / "first");
  std::filesystem::remove(folder / "db.prm");
  // Another seed: a different packing, so the checkpoint does not belong.
  std::string other = small_database;
  other.replace(other.find("Seed = 5"), 8, "Seed = 6");
  write("bad.prm",
        other
          + "subsection Checkpoints\n set Resume from = checkpoint.h5\n"
            "end\n");
  const auto r = compax("database bad.prm -o out");
  std::filesystem::remove(folder / "checkpoint.h5");
  expect_rejected(r, "Resume from");

  expect_prm_rejected(
    "database",
    "subsection Checkpoints\n set Resume from = bad.prm\nend\n",
    "Resume from");
}

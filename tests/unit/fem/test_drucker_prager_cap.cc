// Return mapping of the density-dependent Drucker-Prager Cap: the stress
// after return lies on the yield surface, the consistent tangent matches
// central finite differences of the stress, and trial evaluations leave
// the committed history untouched.
#include "fem/drucker_prager_cap.h"
#include "fem/linear_elastic_material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fem = compax::fem;
using dealii::SymmetricTensor;

namespace
{
  /// A committed state of the default MCC table at relative density rho
  /// loaded by a few increments, so the cap has hardened.
  std::vector<double>
  state(const fem::DruckerPragerCap &m, const double rho)
  {
    std::vector<double> h(m.n_history()), next(m.n_history());
    m.initialize(rho, h);
    return h;
  }

  fem::MaterialIncrement
  increment(const SymmetricTensor<2, 3> &d_eps)
  {
    fem::MaterialIncrement inc;
    inc.strain_increment   = d_eps;
    dealii::Tensor<2, 3> F = dealii::unit_symmetric_tensor<3>();
    F += dealii::Tensor<2, 3>(d_eps);
    inc.deformation_increment = F;
    return inc;
  }

  SymmetricTensor<2, 3>
  strain(double rr, double zz, double tt, double rz)
  {
    SymmetricTensor<2, 3> e;
    e[0][0] = rr;
    e[1][1] = zz;
    e[2][2] = tt;
    e[0][1] = rz;
    return e;
  }

  /// Increments that end on the cap, on the shear line and at the corner
  /// (die compaction, shear under low pressure, mixed).
  std::vector<SymmetricTensor<2, 3>>
  probes(const double rho = 0.5)
  {
    // Scaled with the cap pressure over the stiffness of the density, so
    // every probe leaves the elastic domain at every density.
    const fem::DpcTable table = fem::DpcTable::microcrystalline_cellulose();
    double              pb, dpb;
    table.cap_pressure(rho, pb, dpb);
    const double s = pb / table.parameters(rho).youngs_modulus / 4e-3;
    std::vector<SymmetricTensor<2, 3>> p
      = {strain(-1e-3, -2e-2, -1e-3, 0.0),    // uniaxial compaction: cap
         strain(-4e-3, -4e-3, -4e-3, 0.0),    // hydrostatic: cap
         strain(-2e-4, -6e-3, -2e-4, 3e-3),   // compaction + shear
         strain(1e-3, -3e-3, 1e-3, 4e-3),     // shear at low pressure
         strain(-6e-4, -1.2e-2, 4e-4, 6e-3)}; // mixed
    for (auto &e : p)
      e *= s;
    return p;
  }
} // namespace

TEST(DruckerPragerCap, ReturnedStressLiesOnTheYieldSurface)
{
  const fem::DruckerPragerCap m(fem::DpcTable::microcrystalline_cellulose());
  unsigned int                on_cap = 0, on_shear_line = 0;
  for (const double rho : {0.5, 0.72, 0.88})
    for (const auto &d_eps : probes(rho))
      {
        const auto            h = state(m, rho);
        std::vector<double>   next(m.n_history());
        fem::MaterialResponse r;
        ASSERT_TRUE(m.evaluate(increment(d_eps), h, next, r));
        const double f = m.yield_function(r.stress, rho, next[13]);
        const double scale
          = std::abs(fem::pressure(r.stress)) + fem::von_mises(r.stress);
        EXPECT_LT(std::abs(f), 1e-9 * scale)
          << "rho " << rho << " d_eps " << d_eps;
        EXPECT_GT(fem::von_mises(r.stress) + fem::pressure(r.stress), 0.0);
        // Which surface the state returned to: beyond p_a of the new cap
        // it is the cap, before it the shear line.
        if (fem::pressure(r.stress) > m.cap_transition_pressure(rho, next[13]))
          ++on_cap;
        else
          ++on_shear_line;
      }
  // The probes exercise both surfaces.
  EXPECT_GT(on_cap, 0u);
  EXPECT_GT(on_shear_line, 0u);
}

TEST(DruckerPragerCap, ProbesYield)
{
  // Independent check that the probes are plastic: the elastic trial
  // stress C : d_eps violates the yield function of the initial state.
  const fem::DpcTable table = fem::DpcTable::microcrystalline_cellulose();
  const fem::DruckerPragerCap m(table);
  for (const double rho : {0.5, 0.72, 0.88})
    for (const auto &d_eps : probes(rho))
      {
        const fem::DpcParameters         par = table.parameters(rho);
        const fem::LinearElasticMaterial el(par.youngs_modulus,
                                            par.poisson_ratio);
        std::vector<double>              he(el.n_history()), ne(el.n_history());
        el.initialize(rho, he);
        fem::MaterialResponse re;
        el.evaluate(increment(d_eps), he, ne, re);
        EXPECT_GT(m.yield_function(re.stress, rho, rho), 0.0)
          << "rho " << rho << " d_eps " << d_eps;
      }
}

TEST(DruckerPragerCap, ConsistentTangentMatchesFiniteDifferences)
{
  const fem::DruckerPragerCap m(fem::DpcTable::microcrystalline_cellulose());
  const unsigned int          idx[6][2]
    = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (const double rho : {0.5, 0.72, 0.88})
    for (const auto &d_eps : probes(rho))
      {
        const auto            h = state(m, rho);
        std::vector<double>   next(m.n_history());
        fem::MaterialResponse r;
        ASSERT_TRUE(m.evaluate(increment(d_eps), h, next, r));
        const double scale = r.tangent.norm();
        for (unsigned int k = 0; k < 6; ++k)
          {
            // Perturb the symmetric strain component (both (i,j) and (j,i)
            // when off-diagonal): d sigma = C_ijkl d eps_kl summed.
            const double          step = 1e-7;
            SymmetricTensor<2, 3> e    = d_eps;
            e[idx[k][0]][idx[k][1]] += step;
            fem::MaterialResponse rp, rm;
            ASSERT_TRUE(m.evaluate(increment(e), h, next, rp));
            e[idx[k][0]][idx[k][1]] -= 2 * step;
            ASSERT_TRUE(m.evaluate(increment(e), h, next, rm));
            const SymmetricTensor<2, 3> fd
              = (rp.stress - rm.stress) / (2 * step);
            SymmetricTensor<2, 3> dir;
            dir[idx[k][0]][idx[k][1]]      = 1.0;
            const SymmetricTensor<2, 3> an = r.tangent * dir;
            EXPECT_LT((fd - an).norm(), 1e-5 * scale)
              << "rho " << rho << " component " << k << " d_eps " << d_eps
              << "\nfd " << fd << "\nan " << an;
          }
      }
}

TEST(DruckerPragerCap, TrialEvaluationsLeaveCommittedHistoryUntouched)
{
  const fem::DruckerPragerCap m(fem::DpcTable::microcrystalline_cellulose());
  const auto                  h    = state(m, 0.6);
  const auto                  copy = h;
  std::vector<double>         next(m.n_history());
  fem::MaterialResponse       r;
  for (const auto &d_eps : probes(0.6))
    m.evaluate(increment(d_eps), h, next, r);
  EXPECT_EQ(h, copy);
  // Plastic compaction raised the plastic density, the mass balance the
  // density: rho / det(F).
  const auto e = probes(0.6)[0];
  m.evaluate(increment(e), h, next, r);
  EXPECT_GT(next[13], h[13]);
  const double J = (1 + e[0][0]) * (1 + e[1][1]) * (1 + e[2][2]);
  EXPECT_NEAR(next[6], 0.6 / J, 1e-14);
}

// A row of an unjammed RVE branch has no moduli (NaN): the table refuses
// it, naming the row's density and the values that are out of range.
TEST(DpcTable, RowWithNanModuliIsRefusedWithItsValues)
{
  fem::DpcTable table;
  table.add_row(0.6, 0.0, 40.0, 0.5, 1e5, std::nan(""), std::nan(""));
  table.add_row(0.8, 1e5, 40.0, 0.5, 1e7, 1e9, 0.25);
  try
    {
      table.validate();
      FAIL() << "a NaN Young's modulus was accepted";
    }
  catch (const std::invalid_argument &e)
    {
      const std::string what = e.what();
      EXPECT_NE(what.find("row 1: relative density 0.6"), std::string::npos)
        << what;
      EXPECT_NE(what.find("E nan Pa"), std::string::npos) << what;
    }
}

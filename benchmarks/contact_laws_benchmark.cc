// Contact-law evaluations (force + stiffness) per second on one core, through
// the concrete non-virtual member and through the ContactLaw& interface.
// Each benchmark sweeps a fixed array of overlaps (and, where the law needs
// them, histories and contexts), so the branch pattern is that of a real
// sweep over contacts rather than one repeated input.

#include "dem/contact/bonded_elastoplastic.h"
#include "dem/contact/elastoplastic_material.h"
#include "dem/contact/hertz.h"
#include "dem/contact/multicontact_adhesive.h"
#include "dem/contact/nonlocal_hertz.h"
#include "dem/contact/pair_properties.h"
#include "dem/nonlocal/nonlocal_contact_network.h"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace
{
  using namespace compax::dem;

  constexpr std::size_t n_contacts = 4096;

  // Overlaps uniformly in [lo, hi], fixed seed.
  std::vector<double>
  overlaps(double lo, double hi)
  {
    std::mt19937                           rng(42);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<double>                    g(n_contacts);
    for (double &x : g)
      x = u(rng);
    return g;
  }

  // ---- Hertz: two different MCC-like spheres.
  const HertzLaw &
  hertz()
  {
    static const HertzLaw law
      = HertzLaw::for_pair(100e-6, 2.58e8, 0.3, 150e-6, 1.34e9, 0.3);
    return law;
  }

  void
  BM_Hertz_concrete(benchmark::State &state)
  {
    const HertzLaw           &law = hertz();
    const std::vector<double> g   = overlaps(0.0, 5e-6);
    for (auto _ : state)
      for (const double x : g)
        {
          const ContactResponse r = law.response(x);
          benchmark::DoNotOptimize(r.force);
          benchmark::DoNotOptimize(r.stiffness);
        }
    state.SetItemsProcessed(state.iterations() * n_contacts);
  }

  // The interface pointer is laundered through DoNotOptimize so that the
  // compiler cannot devirtualize the call.
  void
  run_virtual(benchmark::State                  &state,
              const ContactLaw                  &law,
              const std::vector<double>         &g,
              const std::vector<ContactHistory> &h,
              const std::vector<ContactContext> &c)
  {
    const ContactLaw *p = &law;
    benchmark::DoNotOptimize(p);
    for (auto _ : state)
      for (std::size_t i = 0; i < g.size(); ++i)
        {
          const ContactResponse r = p->evaluate(g[i], h[i], c[i]);
          benchmark::DoNotOptimize(r.force);
          benchmark::DoNotOptimize(r.stiffness);
        }
    state.SetItemsProcessed(state.iterations() * g.size());
  }

  void
  BM_Hertz_virtual(benchmark::State &state)
  {
    run_virtual(state,
                hertz(),
                overlaps(0.0, 5e-6),
                std::vector<ContactHistory>(n_contacts),
                std::vector<ContactContext>(n_contacts));
  }

  // ---- Bonded elasto-plastic: Du et al. (Gonzalez 2018, Sec. 3.1).
  const BondedElastoplasticLaw &
  bonded()
  {
    static const BondedElastoplasticLaw law = [] {
      ElastoplasticMaterial m;
      m.youngs_modulus    = 233e9;
      m.poisson_ratio     = 0.3;
      m.plastic_stiffness = 12.1e9;
      m.plastic_exponent  = 1.79;
      return BondedElastoplasticLaw::for_pair(m,
                                              1.3e-6,
                                              ElastoplasticMaterial::rigid_wall(
                                                1.79),
                                              rigid,
                                              0.48e6,
                                              0.05);
    }();
    return law;
  }

  const double gamma_max = 28.2e-9;

  ContactHistory
  bonded_history()
  {
    ContactHistory h;
    h[BondedElastoplasticLaw::a_p_slot] = bonded().plastic_radius(gamma_max);
    h[BondedElastoplasticLaw::a_B_slot] = BondedElastoplasticLaw::a_p(h);
    return h;
  }

  std::vector<double>
  bonded_unloading_overlaps()
  {
    const double a_p = BondedElastoplasticLaw::a_p(bonded_history());
    return overlaps(bonded().breakage_overlap(a_p),
                    bonded().plastic_overlap(a_p));
  }

  void
  BM_Bonded_loading_concrete(benchmark::State &state)
  {
    const BondedElastoplasticLaw &law = bonded();
    const std::vector<double>     g   = overlaps(0.0, gamma_max);
    for (auto _ : state)
      for (const double x : g)
        {
          const ContactResponse r = law.response(x, 0.0, 0.0);
          benchmark::DoNotOptimize(r.force);
          benchmark::DoNotOptimize(r.stiffness);
        }
    state.SetItemsProcessed(state.iterations() * n_contacts);
  }

  void
  BM_Bonded_loading_virtual(benchmark::State &state)
  {
    run_virtual(state,
                bonded(),
                overlaps(0.0, gamma_max),
                std::vector<ContactHistory>(n_contacts),
                std::vector<ContactContext>(n_contacts));
  }

  void
  BM_Bonded_unloading_concrete(benchmark::State &state)
  {
    const BondedElastoplasticLaw &law = bonded();
    const ContactHistory          h   = bonded_history();
    const std::vector<double>     g   = bonded_unloading_overlaps();
    for (auto _ : state)
      for (const double x : g)
        {
          const ContactResponse r
            = law.response(x,
                           BondedElastoplasticLaw::a_p(h),
                           BondedElastoplasticLaw::a_B(h));
          benchmark::DoNotOptimize(r.force);
          benchmark::DoNotOptimize(r.stiffness);
        }
    state.SetItemsProcessed(state.iterations() * n_contacts);
  }

  void
  BM_Bonded_unloading_virtual(benchmark::State &state)
  {
    run_virtual(state,
                bonded(),
                bonded_unloading_overlaps(),
                std::vector<ContactHistory>(n_contacts, bonded_history()),
                std::vector<ContactContext>(n_contacts));
  }

  // ---- Nonlocal Hertz: gamma_NL between -10% and +30% of gamma.
  const NonlocalHertzLaw &
  nonlocal()
  {
    static const NonlocalHertzLaw law
      = NonlocalHertzLaw::for_pair(100e-6, 2.58e8, 0.3, 150e-6, 1.34e9, 0.3);
    return law;
  }

  std::vector<ContactContext>
  nonlocal_contexts()
  {
    const std::vector<double>   f = overlaps(-0.5e-6, 1.5e-6);
    std::vector<ContactContext> c(n_contacts);
    for (std::size_t i = 0; i < n_contacts; ++i)
      c[i].nonlocal_overlap = f[i];
    return c;
  }

  void
  BM_NonlocalHertz_concrete(benchmark::State &state)
  {
    const NonlocalHertzLaw           &law = nonlocal();
    const std::vector<double>         g   = overlaps(0.0, 5e-6);
    const std::vector<ContactContext> c   = nonlocal_contexts();
    for (auto _ : state)
      for (std::size_t i = 0; i < n_contacts; ++i)
        {
          const ContactResponse r = law.response(g[i], c[i].nonlocal_overlap);
          benchmark::DoNotOptimize(r.force);
          benchmark::DoNotOptimize(r.stiffness);
        }
    state.SetItemsProcessed(state.iterations() * n_contacts);
  }

  void
  BM_NonlocalHertz_virtual(benchmark::State &state)
  {
    run_virtual(state,
                nonlocal(),
                overlaps(0.0, 5e-6),
                std::vector<ContactHistory>(n_contacts),
                nonlocal_contexts());
  }

  // ---- Multi-contact adhesive, Table 3 (MCC-A), mixed branches: half the
  // contacts are loading (delta_max below delta), half un/reloading or
  // adhesive (delta_max above delta).
  const MulticontactAdhesiveLaw &
  multicontact()
  {
    static const MulticontactAdhesiveLaw law = [] {
      MulticontactAdhesiveLaw::Parameters p;
      p.unloading_stiffness_ratio = 120;
      p.adhesion_stiffness_ratio  = 0.5;
      p.plasticity_depth          = 0.99;
      p.multicontact_prefactor    = 1.3;
      p.poisson_ratio             = 0.3;
      return MulticontactAdhesiveLaw::for_pair(
        100e-6, 2.58e8, 0.3, 150e-6, 1.34e9, 0.3, p);
    }();
    return law;
  }

  std::vector<ContactHistory>
  multicontact_histories(bool loading)
  {
    const std::vector<double>   g = overlaps(0.0, 5e-6);
    std::vector<ContactHistory> h(n_contacts);
    for (std::size_t i = 0; i < n_contacts; ++i)
      h[i][MulticontactAdhesiveLaw::delta_max_slot]
        = loading ? 0.5 * g[i] : 1.1 * g[i] + 0.5e-6;
    return h;
  }

  std::vector<ContactContext>
  multicontact_contexts()
  {
    const std::vector<double>   f = overlaps(-20e6, 0.0);
    std::vector<ContactContext> c(n_contacts);
    for (std::size_t i = 0; i < n_contacts; ++i)
      c[i].particle_pressure = f[i];
    return c;
  }

  void
  multicontact_concrete(benchmark::State &state, bool loading)
  {
    const MulticontactAdhesiveLaw    &law = multicontact();
    const std::vector<double>         g   = overlaps(0.0, 5e-6);
    const std::vector<ContactHistory> h   = multicontact_histories(loading);
    const std::vector<ContactContext> c   = multicontact_contexts();
    for (auto _ : state)
      for (std::size_t i = 0; i < n_contacts; ++i)
        {
          const ContactResponse r
            = law.response(g[i],
                           MulticontactAdhesiveLaw::delta_max(h[i]),
                           c[i].particle_pressure);
          benchmark::DoNotOptimize(r.force);
          benchmark::DoNotOptimize(r.stiffness);
        }
    state.SetItemsProcessed(state.iterations() * n_contacts);
  }

  void
  BM_Multicontact_loading_concrete(benchmark::State &state)
  {
    multicontact_concrete(state, true);
  }

  void
  BM_Multicontact_loading_virtual(benchmark::State &state)
  {
    run_virtual(state,
                multicontact(),
                overlaps(0.0, 5e-6),
                multicontact_histories(true),
                multicontact_contexts());
  }

  void
  BM_Multicontact_unloading_concrete(benchmark::State &state)
  {
    multicontact_concrete(state, false);
  }

  void
  BM_Multicontact_unloading_virtual(benchmark::State &state)
  {
    run_virtual(state,
                multicontact(),
                overlaps(0.0, 5e-6),
                multicontact_histories(false),
                multicontact_contexts());
  }

  // ---- Algorithm 1 on a simple cubic lattice of n^3 spheres compressed by
  // 1% (about 3 n^3 contacts, 10 incidences each): one network build plus a
  // converged fixed point; items = contacts.
  void
  BM_NonlocalFixedPoint_cubic(benchmark::State &state)
  {
    const int                 n = static_cast<int>(state.range(0));
    const double              R = 100e-6, E = 2.58e8, nu = 0.3, d = 1.98 * R;
    const ParticleLaw         law = HertzLaw::for_pair(R, E, nu, R, E, nu);
    std::vector<NonlocalBody> bodies(n * n * n, NonlocalBody{R, E, nu});
    std::vector<NonlocalContactNetwork::Contact> contacts;
    std::vector<double>                          gamma;
    const auto                                   id = [n](int i, int j, int k) {
      return static_cast<std::size_t>((i * n + j) * n + k);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k)
          {
            if (i + 1 < n)
              contacts.push_back(
                {id(i, j, k), id(i + 1, j, k), Eigen::Vector3d::UnitX(), &law});
            if (j + 1 < n)
              contacts.push_back(
                {id(i, j, k), id(i, j + 1, k), Eigen::Vector3d::UnitY(), &law});
            if (k + 1 < n)
              contacts.push_back(
                {id(i, j, k), id(i, j, k + 1), Eigen::Vector3d::UnitZ(), &law});
          }
    gamma.assign(contacts.size(), 2 * R - d);
    NonlocalContactNetwork network;
    std::vector<double>    gamma_nl, force;
    unsigned int           sweeps = 0;
    for (auto _ : state)
      {
        network.build(bodies, contacts);
        const NonlocalFixedPointResult r = solve_nonlocal_fixed_point(
          network, gamma, gamma_nl, force, 1e-12 * R, 100);
        sweeps = r.iterations;
        benchmark::DoNotOptimize(force.data());
      }
    state.SetItemsProcessed(state.iterations() * contacts.size());
    state.counters["contacts"] = contacts.size();
    state.counters["sweeps"]   = sweeps;
  }
} // namespace

BENCHMARK(BM_Hertz_concrete);
BENCHMARK(BM_Hertz_virtual);
BENCHMARK(BM_Bonded_loading_concrete);
BENCHMARK(BM_Bonded_loading_virtual);
BENCHMARK(BM_Bonded_unloading_concrete);
BENCHMARK(BM_Bonded_unloading_virtual);
BENCHMARK(BM_NonlocalHertz_concrete);
BENCHMARK(BM_NonlocalHertz_virtual);
BENCHMARK(BM_Multicontact_loading_concrete);
BENCHMARK(BM_Multicontact_loading_virtual);
BENCHMARK(BM_Multicontact_unloading_concrete);
BENCHMARK(BM_Multicontact_unloading_virtual);
BENCHMARK(BM_NonlocalFixedPoint_cubic)->Arg(10)->Arg(20);

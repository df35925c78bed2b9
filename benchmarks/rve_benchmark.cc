// RVE costs for the issue #4 note: a periodic cell of N monodisperse
// spheres of Material 1 (Gonzalez 2018 Table 1) compacted in uniaxial strain
// from a relative density of 0.6 to 0.75 in 15 steps. Reported per N:
//  - UniaxialPath: the whole 15-step path (FIRE while loose, trust-region
//    Newton once jammed); counter seconds_per_step;
//  - StrainIncrement: the last (jammed) step alone, 0.74 -> 0.75;
//  - CondensedTangent: TangentCalculator::compute (condensed + affine) at
//    0.75;
//  - SixForwardDifferenceSolves: the six re-equilibrations of a
//    forward-difference tangent (strain step 1e-5, the command's default
//    solver tolerances) from the same state, the cost the condensation
//    replaces; SixAccurateForwardDifferenceSolves the same at force
//    tolerance 1e-10, which a finite-difference tangent accurate to 1e-4
//    needs (the comparison at equal accuracy).
// Preparation (packing and loading) is done once per N and not timed.

#include "benchmarks/material1_model.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_bed_system.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"

#include <benchmark/benchmark.h>

#include <algorithm>

#include <map>

namespace
{
  using namespace compax::dem;
  using compax::benchmarks::material1_model;


  Eigen::Matrix3d
  uniaxial(double rho0, double rho)
  {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(2, 2)           = rho0 / rho;
    return F;
  }

  constexpr int    steps     = 15;
  constexpr double rho_start = 0.6, rho_end = 0.75;

  double
  target(int k)
  {
    return rho_start + (rho_end - rho_start) * k / steps;
  }

  /// Packing at 0.6, the state after 14 steps and after 15 steps.
  struct Prepared
  {
    PeriodicBed packing, before_last, loaded;
  };

  const Prepared &
  prepared(std::size_t n)
  {
    static std::map<std::size_t, Prepared> cache;
    auto                                   it = cache.find(n);
    if (it != cache.end())
      return it->second;
    PeriodicPackingSpec spec;
    spec.particle_count      = n;
    spec.sizes.median_radius = 220e-6;
    spec.relative_density    = rho_start;
    spec.seed                = 1;
    Prepared p;
    p.packing        = make_periodic_packing(spec, material1_model());
    PeriodicBed  bed = p.packing;
    RveLoading   loading(material1_model());
    const double rho0 = bed.relative_density();
    for (int k = 1; k <= steps; ++k)
      {
        if (k == steps)
          p.before_last = bed;
        if (!loading.deform_to(bed, uniaxial(rho0, target(k))).converged)
          throw std::runtime_error("benchmark preparation did not converge");
      }
    p.loaded = bed;
    return cache.emplace(n, std::move(p)).first->second;
  }

  void
  UniaxialPath(benchmark::State &state)
  {
    const Prepared &p = prepared(state.range(0));
    for (auto _ : state)
      {
        PeriodicBed  bed = p.packing;
        RveLoading   loading(material1_model());
        const double rho0 = bed.relative_density();
        for (int k = 1; k <= steps; ++k)
          benchmark::DoNotOptimize(
            loading.deform_to(bed, uniaxial(rho0, target(k))).converged);
      }
    state.counters["seconds_per_step"]
      = benchmark::Counter(steps,
                           benchmark::Counter::kIsIterationInvariantRate
                             | benchmark::Counter::kInvert);
  }

  void
  StrainIncrement(benchmark::State &state)
  {
    const Prepared &p          = prepared(state.range(0));
    const double    rho0       = p.packing.relative_density();
    int             iterations = 0;
    for (auto _ : state)
      {
        state.PauseTiming();
        PeriodicBed bed = p.before_last;
        RveLoading  loading(material1_model());
        state.ResumeTiming();
        iterations
          = loading.deform_to(bed, uniaxial(rho0, target(steps))).iterations;
      }
    state.counters["newton_iterations"] = iterations;
  }

  void
  CondensedTangent(benchmark::State &state)
  {
    const Prepared   &p   = prepared(state.range(0));
    PeriodicBed       bed = p.loaded;
    TangentCalculator tangent;
    for (auto _ : state)
      benchmark::DoNotOptimize(
        tangent.compute(bed, material1_model(), ContactBranch::current)
          .condensed(2, 2));
  }

  /// Six forward-difference re-equilibrations with the given force and
  /// step tolerance.
  void
  six_forward_difference_solves(benchmark::State &state, const double tolerance)
  {
    const Prepared    &p = prepared(state.range(0));
    EquilibriumOptions options;
    options.force_tolerance = tolerance;
    options.step_tolerance  = std::min(options.step_tolerance, tolerance);
    int iterations          = 0;
    for (auto _ : state)
      {
        iterations = 0;
        for (int b = 0; b < 6; ++b)
          {
            state.PauseTiming();
            PeriodicBed       bed = p.loaded;
            PeriodicAssembler assembler;
            TrustRegionNewton newton(options);
            Vector6d          e = Vector6d::Zero();
            e[b]                = 1e-5;
            state.ResumeTiming();
            map_affinely(bed,
                         (Eigen::Matrix3d::Identity() + strain_from_voigt(e))
                           * bed.deformation);
            PeriodicBedSystem system(bed, material1_model(), assembler);
            iterations += newton.solve(system).work.iterations;
            benchmark::DoNotOptimize(love_weber_stress(bed)(2, 2));
          }
      }
    state.counters["newton_iterations"] = iterations;
  }

  /// At the command's default tolerance (1e-6): a tangent good to ~1e-2.
  void
  SixForwardDifferenceSolves(benchmark::State &state)
  {
    six_forward_difference_solves(state, EquilibriumOptions{}.force_tolerance);
  }

  /// At 1e-10, the tolerance a finite-difference tangent needs to agree
  /// with the condensed one to 1e-4 (tests/unit/dem/test_rve_homogenization):
  /// the comparison at equal accuracy.
  void
  SixAccurateForwardDifferenceSolves(benchmark::State &state)
  {
    six_forward_difference_solves(state, 1e-10);
  }
} // namespace

BENCHMARK(UniaxialPath)
  ->Arg(250)
  ->Arg(500)
  ->Arg(1000)
  ->Arg(2000)
  ->Unit(benchmark::kMillisecond)
  ->Iterations(1);
BENCHMARK(StrainIncrement)
  ->Arg(250)
  ->Arg(500)
  ->Arg(1000)
  ->Arg(2000)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(CondensedTangent)
  ->Arg(250)
  ->Arg(500)
  ->Arg(1000)
  ->Arg(2000)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(SixForwardDifferenceSolves)
  ->Arg(250)
  ->Arg(500)
  ->Arg(1000)
  ->Arg(2000)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(SixAccurateForwardDifferenceSolves)
  ->Arg(250)
  ->Arg(500)
  ->Arg(1000)
  ->Arg(2000)
  ->Unit(benchmark::kMillisecond);

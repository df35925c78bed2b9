// The cost of one residual of the die's static equilibrium (Gonzalez 2018
// Eq. 12), the evaluation that the relaxations of the bonded path repeat
// hundreds of thousands of times: the §5 bed of Material 1 (6512 spheres of
// R = 220 um in a 10 mm die), deposited and mapped affinely to a relative
// density of 0.64, just past the jamming onset, so that most neighbours
// touch. Argument: the number of OpenMP threads. DieAssembly adds the
// stiffness K (Newton's iterations, FIRE's masses, the L-BFGS seed). Both
// are the same to the bit on every thread count (SolverStiffness tests);
// this reports what the threads buy. Preparation is done once and not
// timed.

#include "benchmarks/material1_model.h"
#include "dem/die/die_setup.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/punch_gap_map.h"

#include <benchmark/benchmark.h>

#include <omp.h>

namespace
{
  using namespace compax::dem;
  using compax::benchmarks::material1_model;

  /// The deposit of the §5 bed, its punch gap closed to rho = 0.64.
  const Bed &
  compacted_bed()
  {
    static const Bed bed = [] {
      DepositionParameters dp;
      dp.n_particles      = 6512;
      dp.die_diameter     = 10e-3;
      dp.seed             = 1;
      Bed            b    = fill_die(dp);
      const DieWalls from = b.walls;
      DieWalls       to   = from;
      to.upper_punch
        = from.lower_punch + from.height() * b.relative_density() / 0.64;
      map_heights(b.particles, from, to, GapParticles::between_punches);
      b.walls = to;
      return b;
    }();
    return bed;
  }

  /// Runs the enclosing benchmark on the number of threads its argument
  /// names, and gives the process its thread count back afterwards.
  class ThreadsOfArgument
  {
  public:
    explicit ThreadsOfArgument(const benchmark::State &state)
        : before(omp_get_max_threads())
    {
      omp_set_num_threads(static_cast<int>(state.range(0)));
    }

    ~ThreadsOfArgument()
    {
      omp_set_num_threads(before);
    }

  private:
    int before;
  };

  void
  DieResidual(benchmark::State &state)
  {
    const ThreadsOfArgument threads(state);
    Bed                     bed = compacted_bed();
    ContactAssembler        assembler;
    Eigen::VectorXd         F;
    ContactSums sums = assembler.residual(bed, material1_model(), F);
    for (auto _ : state)
      {
        sums = assembler.residual(bed, material1_model(), F);
        benchmark::DoNotOptimize(F.data());
      }
    state.counters["pairs"]  = static_cast<double>(bed.contacts.pairs.size());
    state.counters["loaded"] = static_cast<double>(sums.n_loaded);
  }

  void
  DieAssembly(benchmark::State &state)
  {
    const ThreadsOfArgument threads(state);
    Bed                     bed = compacted_bed();
    ContactAssembler        assembler;
    Eigen::VectorXd         F;
    BlockSparseMatrix       K;
    assembler.assemble(bed, material1_model(), F, K);
    for (auto _ : state)
      {
        assembler.assemble(bed, material1_model(), F, K);
        benchmark::DoNotOptimize(F.data());
        benchmark::DoNotOptimize(K.block(0));
      }
    state.counters["pairs"] = static_cast<double>(bed.contacts.pairs.size());
  }
} // namespace

BENCHMARK(DieResidual)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(DieAssembly)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

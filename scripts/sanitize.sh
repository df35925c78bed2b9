#!/usr/bin/env bash
# Debug build with AddressSanitizer and UndefinedBehaviorSanitizer of the unit
# tests, then runs them. Used by CI; run by hand after scripts/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCOMPAX_SANITIZE=ON \
  -DCOMPAX_BUILD_BENCHMARKS=OFF > build-sanitize.log 2>&1 \
  || { cat build-sanitize.log; exit 1; }
targets=$(cmake --build build-sanitize --target help | sed -n 's/^\.\.\. \(compax_[a-z]*_tests\).*/\1/p' | grep -v app || true)
cmake --build build-sanitize -j"$(nproc)" --target ${targets} >> build-sanitize.log 2>&1 \
  || { tail -n 60 build-sanitize.log; exit 1; }
# OpenMPI's own allocations are not ours to report.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The few tests that are whole simulations (minutes at -O0 under ASan) are
# left to the Release run; everything else runs instrumented.
slow='Calibration.RecoversBetaFromAnotherPacking|SolverConsolidation.LooseDeposit|SolverConsolidation.ThousandParticles|PeriodicCellGrid.FindsTheSamePairs|DieProtocol.PunchForcesBalance'
ctest --test-dir build-sanitize -L unit -E "$slow" --output-on-failure \
  --timeout 600 -j"$(nproc)"

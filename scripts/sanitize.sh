#!/usr/bin/env bash
# AddressSanitizer and UndefinedBehaviorSanitizer run of the unit tests. Used by
# CI after the Release suite; run by hand after scripts/setup.sh and the suite.
set -euo pipefail
cd "$(dirname "$0")/.."
# -O1 as the ASan manual advises: keeps every check and stack trace, and runs
# the Eigen-heavy solvers some ten times faster than -O0. -g1 (line tables
# only) is all a sanitizer report needs for file:line stack traces, and
# compiles the deal.II-heavy files twice as fast as -g (fem/tablet_solver.cc:
# 67 s against 144 s, half the object size).
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCOMPAX_SANITIZE=ON \
  -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" \
  -DCOMPAX_BUILD_BENCHMARKS=OFF > build-sanitize.log 2>&1 \
  || { cat build-sanitize.log; exit 1; }
targets=$(cmake --build build-sanitize --target help | sed -n 's/^\.\.\. \(compax_[a-z]*_tests\).*/\1/p' | grep -v app || true)
cmake --build build-sanitize -j"$(nproc)" --target ${targets} >> build-sanitize.log 2>&1 \
  || { tail -n 60 build-sanitize.log; exit 1; }
# OpenMPI's own allocations are not ours to report.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Whole simulations run 50-200 times slower instrumented. The tests that took
# longer than COMPAX_SANITIZE_MAX_SECONDS (default 1 s) in the Release suite
# just run (ctest's cost file) are left to that run, so that the stage fits
# in CI's time; without a cost file every unit test runs instrumented.
max_seconds=${COMPAX_SANITIZE_MAX_SECONDS:-1}
cost_file=build/Testing/Temporary/CTestCostData.txt
slow='^$'
if [[ -f ${cost_file} ]]; then
  slow=$(awk -v max="${max_seconds}" '/^unit\./ && $3 > max { printf "%s^%s$", sep, $1; sep = "|" }' "${cost_file}")
  echo "sanitize: $(tr '|' '\n' <<< "${slow}" | grep -c . || true) unit tests slower than ${max_seconds} s in Release are left to the Release run"
fi
ctest --test-dir build-sanitize -L unit -E "${slow:-^$}" --output-on-failure \
  --timeout 600 -j"$(nproc)"

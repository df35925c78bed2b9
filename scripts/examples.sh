#!/usr/bin/env bash
# Installs compax from a configured and built tree (default build/, as
# scripts/setup.sh leaves it) into a fresh prefix, then configures, builds
# and runs every program in examples/ against that installation with
# find_package(compax). Exits non-zero on any failure.
# Usage: bash scripts/examples.sh [build dir]
# COMPAX_EXAMPLES_DIR=<dir> keeps the installation and example builds there
# (default: a temporary folder, removed after a successful run).
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(realpath "${1:-build}")
examples=(die_compaction rve_strain_path)

if [ -n "${COMPAX_EXAMPLES_DIR:-}" ]; then
  work=$(realpath -m "$COMPAX_EXAMPLES_DIR")
  rm -rf "$work/install"
  mkdir -p "$work"
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/compax-examples.XXXXXX")
fi
prefix="$work/install"

# Runs a step quietly into a log; on failure prints the log and stops.
step() {
  local log="$work/$1.log"
  shift
  "$@" > "$log" 2>&1 || {
    tail -n 60 "$log"
    echo "compax examples: failed: $* (log: $log)" >&2
    exit 1
  }
}

start=$SECONDS
step install cmake --install "$build" --prefix "$prefix"
echo "compax examples: installed into $prefix"
for example in "${examples[@]}"; do
  dir="$work/$example"
  rm -rf "$dir"
  step "$example-configure" cmake -S "examples/$example" -B "$dir" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix"
  step "$example-build" cmake --build "$dir" -j"$(nproc)"
  echo "compax examples: running $example"
  (cd "$dir" && "./$example") || {
    echo "compax examples: $example failed (build: $dir)" >&2
    exit 1
  }
done
echo "compax examples: ${#examples[@]} examples built against the installed" \
  "package and passed ($((SECONDS - start)) s)"
[ -n "${COMPAX_EXAMPLES_DIR:-}" ] || rm -rf "$work"

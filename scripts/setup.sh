#!/usr/bin/env bash
# Installs what compax needs from Debian 12 (when missing), then configures and
# builds it in Release into build/. Safe to run again: it only does what is
# left to do. Usage: bash scripts/setup.sh [extra cmake arguments]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  g++ make cmake pkg-config
  libdeal.ii-dev      # deal.II 9.4 with Trilinos, p4est, HDF5, MPI
  libeigen3-dev
  libboost-math-dev   # Gauss-Legendre rules (dem, interior volumes)
  libhdf5-openmpi-dev
  openmpi-bin
  libgtest-dev
  libbenchmark-dev
  gnuplot-nox         # PNG plots of the results
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "compax setup: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "compax setup: these Debian packages are missing and installing them needs root:" >&2
    echo "  apt-get install ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" > build.log 2>&1 \
  || { cat build.log; echo "compax setup: cmake configure failed" >&2; exit 1; }
cmake --build build -j"$(nproc)" >> build.log 2>&1 \
  || { tail -n 60 build.log; echo "compax setup: build failed (full log: build.log)" >&2; exit 1; }
echo "compax setup: built build/apps/compax"

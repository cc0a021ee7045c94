#!/usr/bin/env bash
# Shared by ./run.sh and ./test.sh: installs whatever Debian 12 packages are
# missing (non-interactively, as root), then configures and builds Release
# into build/. Safe to call repeatedly: it installs and rebuilds only what is
# missing or stale.
#
#   .ci/setup.sh              everything (the program and every test)
#   .ci/setup.sh floorblock   the given targets only (./run.sh: the program)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  g++ cmake ninja-build ccache
  libdeal.ii-dev libgmsh-dev gmsh
  libcli11-dev nlohmann-json3-dev libfmt-dev
  libgtest-dev gnuplot-nox
  libopenturns-dev   # statistics, sampling, reliability (src/uncertainty/)
  libopenblas0   # drop-in BLAS; the default reference BLAS slows direct solvers
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "setup: missing packages and not root; install them: ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# ccache keys on relative paths below the checkout, so a fresh clone in
# another folder (as CI makes) reuses earlier compilations.
export CCACHE_BASEDIR="$PWD"
export CCACHE_NOHASHDIR=1

# Ninja for a new build folder; an existing one keeps the generator it was
# configured with.
generator=()
[ -f build/CMakeCache.txt ] || generator=(-G Ninja)
cmake "${generator[@]}" -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build build -j"$(nproc)" "${targets[@]}"

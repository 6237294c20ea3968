#!/usr/bin/env bash
# Installs what gpdr needs on a Debian machine (only what is missing), then
# configures and builds it in ./build.  Idempotent: a second run with nothing
# changed installs nothing and rebuilds nothing.
#
#   scripts/setup.sh [extra cmake -D options]
#
# Environment: BUILD_DIR (default build), JOBS (default: all cores).
set -euo pipefail
cd "$(dirname "$0")/.."

# pkg-config and locales (localedef's sources): the library's tests.
# clang and its runtimes (libFuzzer, the sanitizers): the shared sanitizer
# build with the fuzz targets (scripts/asan-build.sh).  python3-meshio (with
# python3-numpy): the test that other programs read the .vtu and .msh files.
# pybind11-dev and python3-dev: the Python module gpdr (python/); python3-pytest
# runs its tests; python3-venv, python3-setuptools and python3-wheel serve
# `pip install --no-build-isolation .` (docs/python.md).
packages=(cmake make gcc g++ libcli11-dev libfmt-dev catch2 libgmp-dev pkg-config locales clang
  libclang-rt-14-dev python3-meshio python3-numpy pybind11-dev python3-dev python3-pytest
  python3-venv python3-setuptools python3-wheel)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

build_dir=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc)}
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  # For this machine's processor (GPDR_NATIVE): what this builds runs here.
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DGPDR_WERROR=ON -DGPDR_NATIVE=ON "$@" \
    >/dev/null
elif [ $# -gt 0 ]; then
  cmake "$build_dir" "$@" >/dev/null
fi
cmake --build "$build_dir" -j "$jobs"

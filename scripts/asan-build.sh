#!/bin/sh
# Configures and builds the one clang build with AddressSanitizer, UBSan and
# the libFuzzer targets (build-asan) that every sanitizer test of the
# library shares (scripts/test-asan.sh) and scripts/fuzz.sh uses.
#
#   scripts/asan-build.sh TARGET...
#
# A build-asan configured with another compiler is made again from scratch:
# CMake cannot change a build's compiler.  GCC 12 and clang give false
# warnings in Catch2's headers under sanitizers, so -Werror is off here.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-asan"
if [ -f "$build/CMakeCache.txt" ] &&
    ! grep -q '^CMAKE_CXX_COMPILER:FILEPATH=.*clang' \
        "$build/CMakeCache.txt"; then
    rm -rf "$build"
fi
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DGPDR_SANITIZE=ON -DGPDR_FUZZ=ON -DGPDR_WERROR=OFF >/dev/null
cmake --build "$build" --target "$@" -j"${JOBS:-2}"

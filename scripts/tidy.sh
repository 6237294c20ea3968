#!/usr/bin/env bash
# Runs clang-tidy with the repository's .clang-tidy over the library and the
# program (or the files named), using a compile database in build-tidy.
# Findings are advice: the script reports them and exits 0 unless clang-tidy
# itself fails.
#
#   scripts/tidy.sh                      every .cpp under lib/ and apps/
#   scripts/tidy.sh lib/mesh/insert.cpp  one file
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-tidy
if [ ! -f "$build/compile_commands.json" ]; then
  # (No GCC link-time optimisation flags: clang-tidy does not know them.)
  cmake -S . -B "$build" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DGPDR_BUILD_TESTS=OFF -DGPDR_LTO=OFF \
    >/dev/null
fi
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files 'lib/*.cpp' 'apps/*.cpp')
fi
clang-tidy -p "$build" --quiet "${files[@]}"

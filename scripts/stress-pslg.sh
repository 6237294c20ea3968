#!/bin/sh
# Meshes many random PSLGs whose segments cross, overlap and pass through
# vertices (tests/stress/random_pslg.hpp), each with -C under a time limit,
# checks every mesh against its input with the stress test's own exact check
# (tests/stress/mesh_check.hpp), and prints per switch set and input family
# the counts of wrong outputs, failures (non-zero exit, crash) and hangs,
# with the first seeds of each.  Usage:
#   scripts/stress-pslg.sh [COUNT] [SWITCHES ...]   defaults: 10000; -p -pc -pq20 -pq30
# Environment:
#   THREADS="1 2"     gpdr's -jN values, each a row of its own
#   TIME_LIMIT=10     seconds a run may take before it counts as a hang
#   KEEP=FOLDER       keep there each input that was not right, named by seed
#   STRICT_ANGLES=1   also count small angles opposite an edge spanning a sharp
#                     input angle, which Ruppert's algorithm leaves (mesh_check.hpp)
#   TRIANGLE=/path/to/triangle   also count Triangle 1.6's results on the same inputs
#   BUILD=build       the build folder (configured here if it does not exist)
# Every switch set meshes the same inputs: seeds 1 .. COUNT.  One input is
# reproduced with: build/tests/stress_pslg --mesher build/gpdr --first-seed S --count 1 -pq20
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
count=10000
if [ $# -gt 0 ]; then
    count=$1
    shift
fi
build=${BUILD:-"$root/build"}
[ -f "$build/CMakeCache.txt" ] || cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target gpdr_app stress_pslg -j"${JOBS:-2}" >/dev/null
set -- --count "$count" --time-limit "${TIME_LIMIT:-10}" ${KEEP:+--keep "$KEEP"} \
    ${STRICT_ANGLES:+--strict-angles} "$@"
"$build/tests/stress_pslg" --mesher "$build/gpdr" --threads "${THREADS:-1 2}" "$@"
if [ -n "${TRIANGLE:-}" ]; then
    echo
    "$build/tests/stress_pslg" --mesher "$TRIANGLE" --triangle "$@"
fi

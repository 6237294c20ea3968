#!/bin/sh
# A longer stress run of the parallel refiner: the [stress] test case
# repeated with different random orders (Catch2 --rng-seed changes nothing
# in the case itself, but thread timing differs from run to run).  Usage:
#   scripts/soak-parallel.sh [ROUNDS] [BUILD]   (defaults: 20, build-par)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
rounds=${1:-20}
build=${2:-"$root/build-par"}
cmake -S "$root" -B "$build" -DGPDR_WERROR=ON >/dev/null
cmake --build "$build" --target test_parallel -j"${JOBS:-2}"
i=1
while [ "$i" -le "$rounds" ]; do
    echo "soak round $i/$rounds"
    "$build/tests/test_parallel" "[parallel]" >/dev/null || { echo "failed in round $i"; exit 1; }
    i=$((i + 1))
done
echo "soak: $rounds rounds passed"

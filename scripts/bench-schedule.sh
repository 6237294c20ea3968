#!/usr/bin/env bash
# How far the deterministic schedule's rounds could scale: for the graded
# pipe (-pq20 with poly-samples/grading.c, c = GRADING_C, default 1e-4:
# about 15 million triangles) and a uniformly refined unit square
# (-pq30a1e-7, about 15 million), at each granularity of GRANULARITY
# (default "2 3 4 5 6"), gpdr -V's figures for the rounds: their number,
# leaves per round, work / span (work = triangles created, a leaf's run
# being the unit that cannot be shared; span = the sum over rounds of the
# largest run) and the speed-up that predicts for 4, 16 and 64 threads.
#
#   scripts/bench-schedule.sh
#   GRADING_C=1e-3 SQUARE_AREA=1e-6 GRANULARITY="4 5" scripts/bench-schedule.sh
#   SIMULATE=1 GRANULARITY=5 scripts/bench-schedule.sh
#
# SIMULATE=1 adds the simulation of the rounds across machines
# (docs/scaling.md): the hidden test "[.simulate]" of the parallel layer's
# test program (TEST_PARALLEL, default tests/test_parallel beside GPDR)
# refines the same two inputs at each granularity of SIMULATE_GRANULARITY
# (default 5) with the rounds recorded, and prints, for R = 4, 16 and 64
# ranks owning the leaves in ranges of their Morton order that hold equal
# numbers of triangles: the share of each round's buffer-zone triangles
# that another rank owns than the leaf's, each round's balance (the largest
# rank's work over the mean), the triangles fetched from other ranks and
# those that change ranks as the ranges follow the triangles, each per
# triangle made, and the speed-up the ranks' supersteps allow against the
# one the rounds allow as many threads.  Its inputs are made in memory: the
# pipe read by the test, the square the same as here.
#
# The figures count triangles, not seconds: they are the same on any
# machine and for any -jN (the rounds do not depend on the threads), so
# the runs use two threads whatever the machine has.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
c=${GRADING_C:-1e-4}
area=${SQUARE_AREA:-1e-7}
granularities=${GRANULARITY:-2 3 4 5 6}
lib="$BENCH_DIR/grading-$c.so"
cc -O2 -shared -fPIC "-DGRADING_C=$c" -o "$lib" "$root/poly-samples/grading.c" -lm
cp "$root/poly-samples/pipe.poly" "$BENCH_DIR/pipe.poly"
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' \
  >"$BENCH_DIR/square.poly"

echo "| input | -g | triangles | rounds | leaves per round (fewest / median / most) | work / span | speed-up on 4 / 16 / 64 |"
echo "|---|---:|---:|---:|---|---:|---|"
# row LABEL G INPUT SWITCHES [ARG ...]
row() {
  local label=$1 g=$2 input=$3 switches=$4
  shift 4
  local log="$BENCH_DIR/schedule.log"
  (cd "$BENCH_DIR" && "$GPDR" "-VNEP${switches}j2g$g" "$@" "$input" >"$log" 2>&1) || {
    echo "| $label | $g | failed: $(tail -1 "$log") |"; return; }
  awk -v label="$label" -v g="$g" '
    /Mesh triangles:/ { t = $NF }
    /rounds refining/ { for (i = 1; i <= NF; i++) if ($i == "rounds") r = $(i - 1) }
    /leaves per round:/ { l = $4 " / " $6 " / " $8 }
    /work \/ span/ { ws = $NF }
    /speed-up the rounds allow:/ { s = $5 " / " $9 " / " $12 }
    END { printf "| %s | %s | %s | %s | %s | %s | %s |\n", label, g, t, r, l, ws, s }' "$log"
}
for g in $granularities; do
  row "graded pipe, c = $c" "$g" pipe.poly pq20 --unsuitable "$lib"
done
for g in $granularities; do
  row "unit square, -a$area" "$g" square.poly "pq30a$area"
done

[ -n "${SIMULATE:-}" ] || exit 0
test_parallel=${TEST_PARALLEL:-$(dirname "$GPDR")/tests/test_parallel}
echo
first=yes
for g in ${SIMULATE_GRANULARITY:-5}; do
  log="$BENCH_DIR/simulate.log"
  GPDR_SIMULATE_C=$c GPDR_SIMULATE_AREA=$area GPDR_SIMULATE_G=$g \
    "$test_parallel" "[.simulate]" >"$log" 2>&1 || {
    echo "simulation -g$g failed: $(tail -3 "$log")"; continue; }
  # The table's rows; its header once.
  awk -v first="$first" '/^\| input/ || /^\|---/ { if (first == "yes") print; next } /^\|/' "$log"
  first=no
done

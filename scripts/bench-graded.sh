#!/usr/bin/env bash
# The GPDR paper's graded experiment (section 3.1, Figure 5): the pipe model
# meshed with a 20 degree angle bound and the grading function (10),
#   area bound at the centroid = c * (sqrt((x-200)^2 + (y-200)^2) + 1),
# c = 1e-4 (about 17 million triangles with the paper's model).
#
#   scripts/bench-graded.sh [THREADS ...]      gpdr with -j1, then each THREADS
#                                              at each granularity of GRANULARITY
#                                              (default "1 2 3 4 5")
#   GRADING_C=1e-3 scripts/bench-graded.sh 2   a smaller run
#   TRIANGLE_GRADED=/path/to/triangle-graded scripts/bench-graded.sh 2
#
# gpdr loads triunsuitable() from poly-samples/grading.c, compiled here into
# a shared object (--unsuitable).  TRIANGLE_GRADED names a Triangle 1.6 built
# by the user with -DEXTERNAL_TEST and linked with grading.c compiled with the
# same -DGRADING_C (see the comment at the top of grading.c); this script
# never builds Triangle.  MODEL=path/to.poly replaces the pipe.  EXTRA="NEP"
# appends switches to every run (e.g. -N -E -P: write no output files, to time
# the meshing alone).
#
# Prints the table of bench-common.sh: refinement seconds are each program's
# "Quality milliseconds" (-V), total seconds and peak memory come from
# /usr/bin/time, and the triangle count from "Mesh triangles:" (-V).
#
# ROUNDS=N runs the whole table N times (the rows of a round one after the
# other, so that every round meets the machine in the same mood) and ends
# with each row's refinement time, then its total (wall) time, as a ratio
# to -j1's and to Triangle's of the same round, every round and the
# median: on a noisy machine one run proves little either way.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
c=${GRADING_C:-1e-4}
threads=(1 "$@")
input=$(bench_input "${MODEL:-$root/poly-samples/pipe.poly}")

# Built afresh every time: a stale object with another c would silently
# change the experiment.
lib="$BENCH_DIR/grading-$c.so"
cc -O2 -shared -fPIC "-DGRADING_C=$c" -o "$lib" "$root/poly-samples/grading.c" -lm

rounds=${ROUNDS:-1}
rows="$BENCH_DIR/graded-rows.txt"
: >"$rows"
# row ROUND LABEL PROGRAM SWITCHES [ARG ...]: one table row, also kept as
# "round<TAB>label<TAB>refine seconds<TAB>total seconds" for the ratios.
row() {
  local round=$1 label=$2
  shift 2
  local line
  line=$(bench_run "$label" "$@")
  echo "$line"
  printf '%s\t%s\t%s\n' "$round" "$label" "$(echo "$line" | awk -F'|' '{ gsub(/ /, ""); print $8 "\t" $10 }')" >>"$rows"
}

echo "Graded $(basename "$input"), -q20, c = $c"
for round in $(seq "$rounds"); do
  echo
  [ "$rounds" -gt 1 ] && echo "Round $round of $rounds" && echo
  bench_header
  for n in "${threads[@]}"; do
    if [ "$n" = 1 ]; then
      row "$round" "gpdr -j1" "$GPDR" "pq20j1${EXTRA:-}" "$input" --unsuitable "$lib"
      continue
    fi
    for g in ${GRANULARITY:-1 2 3 4 5}; do
      row "$round" "gpdr -j$n -g$g" "$GPDR" "pq20j${n}g$g${EXTRA:-}" "$input" --unsuitable "$lib"
    done
  done
  if [ -n "${TRIANGLE_GRADED:-}" ]; then
    row "$round" "triangle (-DEXTERNAL_TEST)" "$TRIANGLE_GRADED" "pq20u${EXTRA:-}" "$input"
  fi
done

# Ratios of column COLUMN of the rows (3: refinement, 4: total), round by
# round, and their medians.
ratios() {
awk -v column="$1" -F'\t' '
  { t[$1, $2] = $column; if (!($2 in seen)) { seen[$2] = 1; order[++n] = $2 } if ($1 > r) r = $1 }
  function median(a, k,   i, j, x) {
    for (i = 2; i <= k; i++) { x = a[i]; for (j = i - 1; j >= 1 && a[j] > x; j--) a[j + 1] = a[j]; a[j + 1] = x }
    return k % 2 ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2
  }
  END {
    tri = "triangle (-DEXTERNAL_TEST)"
    for (i = 1; i <= n; i++) {
      label = order[i]
      if (label == "gpdr -j1" || label == tri) continue
      line = sprintf("  %-14s vs -j1:", label); k = 0
      for (round = 1; round <= r; round++)
        if (t[round, label] > 0 && t[round, "gpdr -j1"] > 0) { q[++k] = t[round, label] / t[round, "gpdr -j1"]; line = line sprintf(" %.2f", q[k]) }
      if (k > 0) line = line sprintf("  (median %.2f)", median(q, k))
      if ((1, tri) in t) {
        line = line "   vs Triangle:"; k = 0
        for (round = 1; round <= r; round++)
          if (t[round, label] > 0 && t[round, tri] > 0) { q[++k] = t[round, label] / t[round, tri]; line = line sprintf(" %.2f", q[k]) }
        if (k > 0) line = line sprintf("  (median %.2f)", median(q, k))
      }
      print line
    }
  }' "$rows"
}
echo
echo "Refinement time as a ratio to gpdr -j1's (and to Triangle's) of the same round:"
ratios 3
echo
echo "Total time as a ratio to gpdr -j1's (and to Triangle's) of the same round:"
ratios 4

#!/usr/bin/env bash
# The GPDR paper's graded experiment (section 3.1, Figure 5): the pipe model
# meshed with a 20 degree angle bound and the grading function (10),
#   area bound at the centroid = c * (sqrt((x-200)^2 + (y-200)^2) + 1),
# c = 1e-4 (about 17 million triangles with the paper's model).
#
#   scripts/bench-graded.sh [THREADS ...]      gpdr with -j1, then each THREADS
#                                              at each granularity of GRANULARITY
#                                              (default "1 2 3 4")
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

echo "Graded $(basename "$input"), -q20, c = $c"
echo
bench_header
for n in "${threads[@]}"; do
  if [ "$n" = 1 ]; then
    bench_run "gpdr -j1" "$GPDR" "pq20j1${EXTRA:-}" "$input" --unsuitable "$lib"
    continue
  fi
  for g in ${GRANULARITY:-1 2 3 4}; do
    bench_run "gpdr -j$n -g$g" "$GPDR" "pq20j${n}g$g${EXTRA:-}" "$input" --unsuitable "$lib"
  done
done
if [ -n "${TRIANGLE_GRADED:-}" ]; then
  bench_run "triangle (-DEXTERNAL_TEST)" "$TRIANGLE_GRADED" "pq20u${EXTRA:-}" "$input"
fi

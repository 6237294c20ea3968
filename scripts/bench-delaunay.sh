#!/usr/bin/env bash
# Delaunay triangulation of uniform random points:
#
#   scripts/bench-delaunay.sh [N ...]          default: 1000000 10000000
#   TRIANGLE=/path/to/triangle scripts/bench-delaunay.sh
#
# Prints a Markdown table: per program, stage seconds, wall seconds and peak
# memory.  Triangle's "read+tri" column holds only its Delaunay time (it does
# not time reading); compare totals for the whole job.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
sizes=("$@")
((${#sizes[@]})) || sizes=(1000000 10000000)

bench_header
for n in "${sizes[@]}"; do
  input="$BENCH_DIR/random-$n.node"
  random_points "$n" "$input"
  bench_run gpdr "$GPDR" "" "$input"
  if [ -n "${TRIANGLE:-}" ]; then
    bench_run triangle "$TRIANGLE" "" "$input"
  fi
done

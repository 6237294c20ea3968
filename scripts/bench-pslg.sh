#!/usr/bin/env bash
# Constrained Delaunay triangulation of a large PSLG a
# fractal coastline with 100 islands (scripts/make-coastline.py), -p only.
#
#   scripts/bench-pslg.sh [SEGMENTS ...]        default: 1000000
#   TRIANGLE=/path/to/triangle scripts/bench-pslg.sh
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
sizes=("$@")
((${#sizes[@]})) || sizes=(1000000)

bench_header
for n in "${sizes[@]}"; do
  input="$BENCH_DIR/coast-$n.poly"
  [ -f "$input" ] || python3 "$root/scripts/make-coastline.py" "$n" "$input"
  bench_run gpdr "$GPDR" "p" "$input"
  if [ -n "${TRIANGLE:-}" ]; then
    bench_run triangle "$TRIANGLE" "p" "$input"
  fi
done

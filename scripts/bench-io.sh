#!/usr/bin/env bash
# Reading and writing Triangle's files at scale the
# Delaunay triangulation of N random points (about 2N triangles) is written
# as .node/.ele, then read back with -r (no output: -NEP).  Prints each
# program's "Output milliseconds" for the write and gpdr's "Read
# milliseconds" for the read.  Triangle, when TRIANGLE names a binary, does
# the same two runs (it does not time its reading separately: its -r total
# is shown).
#
#   scripts/bench-io.sh [N]        default 5000000 (10 million triangles)
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
n=${1:-5000000}
input="$BENCH_DIR/random-$n.node"
random_points "$n" "$input"

run() {  # LABEL PROGRAM ARGS...: prints "label write_s read_s read_total_s"
  local label=$1 program=$2 dir
  dir=$(mktemp -d "$BENCH_DIR/io.XXXXXX")
  ln -s "$input" "$dir/p.node"
  (cd "$dir" && "$program" -V p.node >write.log 2>&1)
  (cd "$dir" && /usr/bin/time -f "%e" -o time.log "$program" -rVNEP p.1 >read.log 2>&1)
  printf "| %s | %s | %s | %s | %s |\n" "$label" "$(count "$dir/write.log" "Mesh triangles:")" \
    "$(ms "$dir/write.log" "Output")" "$(ms "$dir/read.log" "Read")" "$(cat "$dir/time.log")"
  rm -rf "$dir"
}

echo "| program | triangles | write .node+.ele s | read .node+.ele s | -r run total s |"
echo "|---|---:|---:|---:|---:|"
run gpdr "$GPDR"
if [ -n "${TRIANGLE:-}" ]; then run triangle "$TRIANGLE"; fi

#!/usr/bin/env bash
# Delaunay triangulation of uniform random points:
#
#   scripts/bench-delaunay.sh [N ...]          default: 1000000 10000000
#   TRIANGLE=/path/to/triangle THREADS="1 2" ROUNDS=3 NOWRITE=1 scripts/bench-delaunay.sh
#
# THREADS lists gpdr's -j values (default: 1 2); TRIANGLE names a Triangle
# binary to run beside it.  The runs are interleaved: each of the ROUNDS
# rounds (default 3) runs every program once, in turn, so that a busy
# machine slows them alike; the table shows each one's medians.  NOWRITE=1
# adds -NEP: no output files, so the run is reading and triangulating only.
#
# Columns: gpdr's "Read milliseconds" and "Delaunay milliseconds" from -V;
# Triangle does not time its reading, so its read column is its total less
# its Delaunay and output times.  Total is the program's own total running
# time, wall and peak memory come from /usr/bin/time.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
sizes=("$@")
((${#sizes[@]})) || sizes=(1000000 10000000)
read -r -a threads <<<"${THREADS:-1 2}"
rounds=${ROUNDS:-3}
switches=""
[ "${NOWRITE:-0}" = 1 ] && switches="NEP"

samples=$(mktemp -d "$BENCH_DIR/delaunay.XXXXXX")
trap 'rm -rf "$samples"' EXIT

# The programs of one round, as "label|program|switches".
programs=()
for j in "${threads[@]}"; do programs+=("gpdr|$GPDR|${switches}j$j"); done
if [ -n "${TRIANGLE:-}" ]; then programs+=("triangle|$TRIANGLE|$switches"); fi

echo "| input | program | switches | rounds | read ms | Delaunay ms | total ms | wall s | peak MiB |"
echo "|---|---|---|---:|---:|---:|---:|---:|---:|"
for n in "${sizes[@]}"; do
  input="$BENCH_DIR/random-$n.node"
  random_points "$n" "$input"
  for ((r = 1; r <= rounds; r++)); do
    for i in "${!programs[@]}"; do
      IFS='|' read -r label program sw <<<"${programs[$i]}"
      line=$(bench_sample "$program" "$sw" "$input")
      if [ "$line" = failed ]; then
        echo "| $(basename "$input") | $label | -$sw | failed: $(tail -1 "$BENCH_DIR/run.log") |"
      else
        echo "$line" >>"$samples/$n.$i"
      fi
    done
  done
  for i in "${!programs[@]}"; do
    [ -s "$samples/$n.$i" ] || continue
    IFS='|' read -r label program sw <<<"${programs[$i]}"
    read -r read_ms dl_ms total_ms wall peak <<<"$(median_columns "$samples/$n.$i")"
    echo "| $(basename "$input") | $label | -$sw | $(wc -l <"$samples/$n.$i") | $read_ms | $dl_ms | $total_ms | $wall | $((peak / 1024)) |"
  done
done
rm -f "$BENCH_DIR"/random-*.1.*

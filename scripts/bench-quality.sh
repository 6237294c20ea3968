#!/usr/bin/env bash
# Mesh sizes and times of quality refinement, against Triangle 1.6 where
# TRIANGLE names a binary, and of each Steiner point placement.
#
#   scripts/bench-quality.sh [MODEL.poly ...]
#   TRIANGLE=/path/to/triangle scripts/bench-quality.sh
#   ANGLES="30 33" AREA_TRIANGLES=2000 scripts/bench-quality.sh
#
# Models (default): poly-samples/flow.poly and pipe.poly, and the generated
# models of tests/data/models (scripts/make-models.py writes them when they
# are missing).  For each model, at each minimum angle of ANGLES (default
# 20 25 30 32 33 34, -pq<angle>), with an area bound alone (-pa<A>, A the
# bounding box's area over AREA_TRIANGLES, default 4000), and with both at
# 33 and 34 degrees (-pq33a<A>, -pq34a<A>):
#   - table 1: triangles of gpdr -j1, -j2 and Triangle, the ratios -j1 and
#     -j2 to Triangle (or -j2 to -j1 without Triangle), and the wall times;
#     then the median and largest -j1 / Triangle ratio;
#   - table 2: triangles of each placement at 30 degrees (gpdr -P0
#     circumcentre, -P1 off-centre, -P2 the paper's optimisation; -j1) and
#     off-centre / circumcentre.
# Times are wall-clock seconds of whole runs (reading, triangulating,
# refining, writing): the models are small, so they are coarse and noisy.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
models=("$@")
if ((${#models[@]} == 0)); then
  [ -f "$root/tests/data/models/channel.poly" ] || python3 "$root/scripts/make-models.py"
  models=("$root/poly-samples/flow.poly" "$root/poly-samples/pipe.poly")
  for m in channel pipe-section coastline star crossing; do models+=("$root/tests/data/models/$m.poly"); done
fi
read -r -a angles <<<"${ANGLES:-20 25 30 32 33 34}"
area_triangles=${AREA_TRIANGLES:-4000}
work="$BENCH_DIR/quality"
mkdir -p "$work"

# run PROGRAM SWITCHES MODEL: "triangles seconds" of one quiet run, or
# "failed -" (its last message goes to stderr).
run() {
  local program=$1 switches=$2 model=$3 log="$work/run.log"
  local input start end
  input="$work/$(basename "$model")"
  cp -f "$model" "$input"
  rm -f "${input%.poly}".1.*
  start=$(date +%s.%N)
  if (cd "$work" && timeout "${RUN_TIMEOUT:-300}" "$program" "-Q$switches" "$(basename "$input")" >"$log" 2>&1); then
    end=$(date +%s.%N)
    echo "$(ele_count "${input%.poly}.1.ele") $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }')"
  else
    echo "bench-quality: $(basename "$program") -$switches $(basename "$model"): $(tail -1 "$log")" >&2
    echo "failed -"
  fi
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%.3f", a / b; else print "-" }'; }

# The -a bound of a model: its bounding box's area over area_triangles.
area_bound() {
  awk -v n="$area_triangles" '
    /^[[:space:]]*#/ || NF == 0 { next }
    header == 0 { vertices = $1; header = 1; next }
    seen < vertices { x = $2; y = $3; seen++
      if (seen == 1 || x < x0) x0 = x; if (seen == 1 || x > x1) x1 = x
      if (seen == 1 || y < y0) y0 = y; if (seen == 1 || y > y1) y1 = y }
    END { printf "%.6g", (x1 - x0) * (y1 - y0) / n }' "$1"
}

ratios=()
if [ -n "${TRIANGLE:-}" ]; then
  echo "| model | switches | -j1 | -j2 | Triangle | -j1 / T | -j2 / T | -j1 s | -j2 s | Triangle s |"
  echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
else
  echo "| model | switches | -j1 | -j2 | -j2 / -j1 | -j1 s | -j2 s |"
  echo "|---|---|---:|---:|---:|---:|---:|"
fi
for m in "${models[@]}"; do
  name=$(basename "${m%.poly}")
  settings=()
  for a in "${angles[@]}"; do settings+=("pq$a"); done
  settings+=("pa$(area_bound "$m")" "pq33a$(area_bound "$m")" "pq34a$(area_bound "$m")")
  for s in "${settings[@]}"; do
    read -r n1 t1 <<<"$(run "$GPDR" "${s}j1" "$m")"
    read -r n2 t2 <<<"$(run "$GPDR" "${s}j2" "$m")"
    if [ -n "${TRIANGLE:-}" ]; then
      read -r nt tt <<<"$(run "$TRIANGLE" "$s" "$m")"
      r1=$(ratio "$n1" "$nt")
      [ "$r1" = "-" ] || ratios+=("$r1")
      echo "| $name | -$s | $n1 | $n2 | $nt | $r1 | $(ratio "$n2" "$nt") | $t1 | $t2 | $tt |"
    else
      echo "| $name | -$s | $n1 | $n2 | $(ratio "$n2" "$n1") | $t1 | $t2 |"
    fi
  done
done
if ((${#ratios[@]})); then
  printf '%s\n' "${ratios[@]}" | sort -g | awk '{ v[NR] = $1 } END {
    m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "\n-j1 / Triangle over %d runs: median %.3f, smallest %.3f, largest %.3f\n", NR, m, v[1], v[NR] }'
fi

echo
echo "| model | -P0 circumcentre q30 | -P1 off-centre q30 | -P2 optimisation q30 | off-centre / circumcentre |"
echo "|---|---:|---:|---:|---:|"
for m in "${models[@]}"; do
  read -r c _ <<<"$(run "$GPDR" pq30j1P0 "$m")"
  read -r o _ <<<"$(run "$GPDR" pq30j1P1 "$m")"
  read -r p _ <<<"$(run "$GPDR" pq30j1P2 "$m")"
  echo "| $(basename "${m%.poly}") | $c | $o | $p | $(ratio "$o" "$c") |"
done

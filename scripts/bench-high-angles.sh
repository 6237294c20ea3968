#!/usr/bin/env bash
# Refinement above 34 degrees: whether each run ends with the bound met, its
# triangles and seconds, against Triangle 1.6 where TRIANGLE names a binary
# (built outside the repository; this script never builds it).
#
#   scripts/bench-high-angles.sh [MODEL.poly ...]
#   TRIANGLE=/path/to/triangle scripts/bench-high-angles.sh
#   ANGLES="35 36" RANDOM_PSLGS=12 TIME_LIMIT=30 scripts/bench-high-angles.sh
#
# Models (default): poly-samples/flow.poly and pipe.poly, the generated
# models of tests/data/models (scripts/make-models.py writes them when they
# are missing), and RANDOM_PSLGS (default 12) random PSLGs: a fractal star
# of 24 to 90 vertices with up to three holes and sometimes a free segment
# (scripts/pslg.py's shapes, seeds 1, 2, ...).  Each at each angle of ANGLES
# (default 35 36 37 38), -pq<angle>, gpdr with -j1, each program stopped
# after TIME_LIMIT seconds (default 30).
#
# A gpdr run ends "met" or, when the bound was out of reach, "reached A" (the
# angle its warning names); a Triangle run ends or does not end in the time.
# Then, over the runs where Triangle ends: how many gpdr ends with the bound
# met and the largest gpdr / Triangle ratio; over those where it does not:
# how many gpdr ends with the bound met.  Times are wall-clock seconds of
# whole runs: coarse, on small models.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
read -r -a angles <<<"${ANGLES:-35 36 37 38}"
limit=${TIME_LIMIT:-30}
work="$BENCH_DIR/high-angles"
mkdir -p "$work"

models=("$@")
if ((${#models[@]} == 0)); then
  [ -f "$root/tests/data/models/channel.poly" ] || python3 "$root/scripts/make-models.py"
  models=("$root/poly-samples/flow.poly" "$root/poly-samples/pipe.poly")
  for m in channel pipe-section coastline star crossing; do models+=("$root/tests/data/models/$m.poly"); done
  PYTHONPATH="$root/scripts" python3 - "$work" "${RANDOM_PSLGS:-12}" <<'EOF'
import math, random, sys
from pslg import circle, fractal_star, write_poly
out, count = sys.argv[1], int(sys.argv[2])
for seed in range(1, count + 1):
    rng = random.Random(seed)
    loops = [fractal_star(0, 0, 100, rng.choice([24, 40, 60, 90]), rng)]
    holes = []
    for _ in range(rng.randint(0, 3)):
        a, d = rng.uniform(0, 2 * math.pi), rng.uniform(20, 45)
        cx, cy = d * math.cos(a), d * math.sin(a)
        if any(math.hypot(cx - hx, cy - hy) < 30 for hx, hy in holes):
            continue
        r = rng.uniform(4, 12)
        if rng.random() < 0.5:
            loops.append(circle(cx, cy, r, rng.randint(6, 20), rng.uniform(0, 1)))
        else:
            loops.append(fractal_star(cx, cy, r, rng.randint(8, 24), rng))
        holes.append((cx, cy))
    extra = []
    if rng.random() < 0.5:
        x0, y0 = rng.uniform(-40, -10), rng.uniform(-40, 40)
        extra.append([(x0, y0), (x0 + rng.uniform(5, 20), y0 + rng.uniform(-10, 10))])
    write_poly(f"{out}/random-{seed:02d}.poly", [f"a random PSLG, seed {seed}"], loops, holes,
               [1] + [2] * (len(loops) - 1), extra)
EOF
  for ((s = 1; s <= ${RANDOM_PSLGS:-12}; s++)); do models+=("$(printf "%s/random-%02d.poly" "$work" "$s")"); done
fi

# run PROGRAM SWITCHES MODEL: "triangles seconds outcome" of one run in
# $work (outcome: met, reached A, or - when it did not end in time).
run() {
  local program=$1 switches=$2 model=$3 log="$work/run.log" name start end status
  name=$(basename "$model")
  [ "$model" -ef "$work/$name" ] || cp -f "$model" "$work/$name"
  rm -f "$work/${name%.poly}".1.*
  start=$(date +%s.%N)
  status=0
  (cd "$work" && timeout "$limit" "$program" "-$switches" "$name" >"$log" 2>&1) || status=$?
  end=$(date +%s.%N)
  local seconds
  seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  if [ "$status" -ne 0 ] || [ ! -f "$work/${name%.poly}.1.ele" ]; then
    echo "- $seconds -"
    return
  fi
  local outcome=met reached
  reached=$(grep -o 'reached [0-9.]* degrees' "$log" | head -1 | awk '{ print $2 }') || true
  [ -n "$reached" ] && outcome="reached $reached"
  echo "$(ele_count "$work/${name%.poly}.1.ele") $seconds $outcome"
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%.3f", a / b; else print "-" }'; }

if [ -n "${TRIANGLE:-}" ]; then
  echo "| model | angle | gpdr -j1 | s | gpdr ends | Triangle | s | gpdr / Triangle |"
  echo "|---|---:|---:|---:|---|---:|---:|---:|"
else
  echo "| model | angle | gpdr -j1 | s | gpdr ends |"
  echo "|---|---:|---:|---:|---|"
fi
t_ended=0 t_ended_met=0 t_open=0 t_open_met=0 met=0 runs=0 largest=0
for m in "${models[@]}"; do
  for a in "${angles[@]}"; do
    read -r n1 s1 o1 <<<"$(run "$GPDR" "pq${a}j1" "$m")"
    runs=$((runs + 1))
    [ "$o1" = met ] && met=$((met + 1))
    [ "$n1" = - ] && o1="did not end in ${limit} s"
    if [ -n "${TRIANGLE:-}" ]; then
      read -r nt st _ <<<"$(run "$TRIANGLE" "Qpq${a}" "$m")"
      r=$(ratio "$n1" "$nt")
      if [ "$nt" = - ]; then
        t_open=$((t_open + 1))
        [ "$o1" = met ] && t_open_met=$((t_open_met + 1))
        nt="did not end in ${limit} s"
        r=-
      else
        t_ended=$((t_ended + 1))
        [ "$o1" = met ] && t_ended_met=$((t_ended_met + 1))
        [ "$r" != - ] && largest=$(awk -v a="$r" -v b="$largest" 'BEGIN { print (a > b ? a : b) }')
      fi
      echo "| $(basename "${m%.poly}") | $a | $n1 | $s1 | $o1 | $nt | $st | $r |"
    else
      echo "| $(basename "${m%.poly}") | $a | $n1 | $s1 | $o1 |"
    fi
  done
done
echo
echo "gpdr ends with the bound met on $met of $runs runs."
if [ -n "${TRIANGLE:-}" ]; then
  echo "Where Triangle ends ($t_ended runs), gpdr meets the bound on $t_ended_met; the largest gpdr / Triangle ratio is $largest."
  echo "Where Triangle does not end ($t_open runs), gpdr meets the bound on $t_open_met."
fi

#!/usr/bin/env bash
# How much two refinements running at once slow each other down on this
# machine (shared caches and memory bandwidth, or a hypervisor's sibling
# threads): the floor under any two-thread speed-up.  Refines the graded pipe
# of bench-graded.sh with -j1 alone, then two -j1 runs at once (separate
# folders), ROUNDS times, and prints every run's refinement seconds and
#   R = (mean refinement of the concurrent runs) / (mean of the lone runs).
# Two workers that each do half of the work can at best refine in R/2 of one
# thread's time, before any cost of the parallel algorithm itself.
#
#   scripts/bench-contention.sh              GRADING_C=1e-4, ROUNDS=3
#   CPUS="0 1" scripts/bench-contention.sh   pin the two runs to CPUs 0 and 1
#                                            (taskset), the lone runs to CPU 0
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
c=${GRADING_C:-1e-4}
rounds=${ROUNDS:-3}
read -r -a cpus <<<"${CPUS:-}"

lib="$BENCH_DIR/grading-$c.so"
cc -O2 -shared -fPIC "-DGRADING_C=$c" -o "$lib" "$root/poly-samples/grading.c" -lm
for d in a b; do
  mkdir -p "$BENCH_DIR/contention-$d"
  cp -f "${MODEL:-$root/poly-samples/pipe.poly}" "$BENCH_DIR/contention-$d/model.poly"
done

# refine DIR CPU: runs gpdr -j1 in DIR (pinned to CPU when given) and prints
# its refinement seconds.
refine() {
  local pin=()
  if [ -n "$2" ]; then pin=(taskset -c "$2"); fi
  ( cd "$1" && "${pin[@]}" "$GPDR" -VNEPpq20j1 --unsuitable "$lib" model.poly >run.log 2>&1 )
  ms "$1/run.log" "Quality"
}

echo "Graded $(basename "${MODEL:-pipe.poly}"), -q20, c = $c, -j1, $rounds rounds"
alone=() together=()
for r in $(seq "$rounds"); do
  alone+=("$(refine "$BENCH_DIR/contention-a" "${cpus[0]:-}")")
  refine "$BENCH_DIR/contention-a" "${cpus[0]:-}" >"$BENCH_DIR/contention-a.s" &
  refine "$BENCH_DIR/contention-b" "${cpus[1]:-}" >"$BENCH_DIR/contention-b.s"
  wait
  together+=("$(cat "$BENCH_DIR/contention-a.s")" "$(cat "$BENCH_DIR/contention-b.s")")
  echo "round $r: alone ${alone[-1]} s; at once ${together[-2]} s and ${together[-1]} s"
done
awk -v a="${alone[*]}" -v t="${together[*]}" 'BEGIN {
  na = split(a, x, " "); nt = split(t, y, " ");
  for (i = 1; i <= na; i++) sa += x[i]; for (i = 1; i <= nt; i++) st += y[i];
  r = (st / nt) / (sa / na);
  printf "R = %.2f: two workers can at best refine in %.2fx one thread'"'"'s time\n", r, r / 2 }'

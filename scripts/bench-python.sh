#!/usr/bin/env bash
# gpdr's Python module against the triangle package (Triangle 1.6 inside a
# Cython wrapper), on the same inputs, each measurement in a fresh
# interpreter:
#
#   TRIANGLE_PY=path/to/triangle-checkout scripts/bench-python.sh
#
#   - triangulate() of 1,000,000 uniform random points with '' and 'q', and
#     of poly-samples/pipe.poly with 'pq20a0.01' (about 17 million
#     triangles): seconds of the call and peak memory, gpdr with threads=1;
#   - two Python threads each meshing 1,000,000 points with '' at once,
#     against the same two calls in a row (gpdr with threads=1), and the
#     same two calls in two processes at once: what the machine itself
#     allows (shared cores, caches, memory bandwidth).
#
# TRIANGLE_PY is a checkout of the triangle package's repository
# (github.com/drufat/triangle) with its c/ submodule, which holds Triangle's
# triangle.c.  The script copies it into $BENCH_DIR/triangle-py and compiles
# the package's shipped triangle/core.c there (Debian's Cython is too old to
# regenerate it from core.pyx): Triangle's code is never built or kept in
# this repository.
#
# Environment: GPDR_PYTHONPATH (default build/python: the module assembled
# by `cmake --build build --target gpdr_python`), PYTHON (default
# /usr/bin/python3), BENCH_DIR (default /tmp/gpdr-bench), REPEATS (default 3:
# the fastest of REPEATS runs is shown, each module's runs alternating),
# POINTS (default 1000000), PIPE_SWITCHES (default pq20a0.01).
# Figures are for comparing as ratios within one run of the script: these
# machines are small and noisy.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
python=${PYTHON:-/usr/bin/python3}
bench_dir=${BENCH_DIR:-/tmp/gpdr-bench}
gpdr_path=${GPDR_PYTHONPATH:-$root/build/python}
repeats=${REPEATS:-3}
points=${POINTS:-1000000}
pipe_switches=${PIPE_SWITCHES:-pq20a0.01}

if [ -z "${TRIANGLE_PY:-}" ] || [ ! -f "$TRIANGLE_PY/triangle/core.c" ] ||
  [ ! -f "$TRIANGLE_PY/c/triangle.c" ]; then
  echo "bench-python: set TRIANGLE_PY to a checkout of github.com/drufat/triangle with its c/" >&2
  echo "submodule (git clone --recursive): triangle/core.c and c/triangle.c are needed" >&2
  exit 2
fi
if ! ls "$gpdr_path"/gpdr/_core*.so >/dev/null 2>&1; then
  echo "bench-python: no gpdr module in $gpdr_path (cmake --build build --target gpdr_python," >&2
  echo "or set GPDR_PYTHONPATH to where it is)" >&2
  exit 2
fi
mkdir -p "$bench_dir"
bench_dir=$(cd "$bench_dir" && pwd)
case "$bench_dir/" in
  "$root"/*)
    echo "bench-python: BENCH_DIR is inside the repository; Triangle's code stays out of it" >&2
    exit 2
    ;;
esac

# The triangle package, built in place in a copy of the checkout.
package="$bench_dir/triangle-py"
if ! ls "$package"/triangle/core*.so >/dev/null 2>&1; then
  echo "bench-python: building the triangle package in $package" >&2
  rm -rf "$package"
  mkdir -p "$package"
  cp -r "$TRIANGLE_PY"/. "$package"/
  rm -rf "$package/.git"
  (cd "$package" && "$python" setup.py -q build_ext --inplace >"$bench_dir/triangle-py.log" 2>&1) || {
    tail -20 "$bench_dir/triangle-py.log" >&2
    exit 1
  }
fi

# The pipe as arrays, read once with gpdr's reader, so that both modules
# start from the same numpy arrays and neither process imports the other.
pipe="$bench_dir/pipe.npz"
PYTHONPATH="$gpdr_path" "$python" - "$root/poly-samples" "$pipe" <<'PY'
import sys
import numpy as np
import gpdr
tri = gpdr.load(sys.argv[1], "pipe")
np.savez(sys.argv[2], **{k: tri[k] for k in ("vertices", "segments", "holes")})
PY

driver="$bench_dir/bench_python.py"
cat >"$driver" <<'PY'
"""One measurement: python bench_python.py MODULE CASE ARG; prints
'seconds peak_MiB call_MiB triangles'."""
import resource
import sys
import threading
import time

import numpy as np

module, case, arg = sys.argv[1:4]
if module == "gpdr":
    import gpdr as m
    extras = {"threads": 1}
else:
    import triangle as m
    extras = {}


def peak_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def random_points(seed, count):
    return np.random.default_rng(seed).random((count, 2))


if case in ("random", "pipe"):
    if case == "random":
        tri, opts = {"vertices": random_points(1, int(arg))}, sys.argv[4]
    else:
        tri, opts = dict(np.load(arg)), sys.argv[4]
    before = peak_mib()
    start = time.perf_counter()
    mesh = m.triangulate(tri, opts, **extras)
    seconds = time.perf_counter() - start
    count = len(mesh["triangles"])
elif case == "processes":  # the machine's own floor: two processes at once
    import multiprocessing as mp

    def child(seed, barrier, times):
        tri = {"vertices": random_points(seed, int(arg))}
        barrier.wait()
        began = time.perf_counter()  # CLOCK_MONOTONIC: one clock for every process
        mesh = m.triangulate(tri, "", **extras)
        times.put((began, time.perf_counter(), len(mesh["triangles"])))

    context = mp.get_context("fork")
    barrier, times = context.Barrier(2), context.Queue()
    children = [context.Process(target=child, args=(seed, barrier, times)) for seed in (1, 2)]
    before = peak_mib()
    for c in children:
        c.start()
    spans = [times.get() for _ in children]
    for c in children:
        c.join()
    seconds = max(s[1] for s in spans) - min(s[0] for s in spans)
    count = sum(s[2] for s in spans)
else:  # "together" or "in-a-row": two sets of points in two Python threads
    sets = [random_points(seed, int(arg)) for seed in (1, 2)]
    results = [None, None]

    def run(i):
        results[i] = m.triangulate({"vertices": sets[i]}, "", **extras)

    before = peak_mib()
    start = time.perf_counter()
    if case == "together":
        workers = [threading.Thread(target=run, args=(i,)) for i in range(2)]
        for w in workers:
            w.start()
        for w in workers:
            w.join()
    else:
        run(0)
        run(1)
    seconds = time.perf_counter() - start
    count = sum(len(r["triangles"]) for r in results)
print(f"{seconds:.3f} {peak_mib():.0f} {peak_mib() - before:.0f} {count}")
PY

# measure MODULE CASE ARG [OPTS]: the fastest of $repeats runs, as
# "seconds peak_MiB call_MiB triangles".
declare -A best
measure_all() {
  local key=$1
  shift
  local module line
  for ((r = 0; r < repeats; r++)); do
    for module in triangle gpdr; do
      local path="$package"
      [ "$module" = gpdr ] && path="$gpdr_path"
      line=$(PYTHONPATH="$path" "$python" "$driver" "$module" "$@" 2>"$bench_dir/driver.log") || {
        echo "bench-python: $module $*: $(tail -1 "$bench_dir/driver.log")" >&2
        line="- - - -"
      }
      local old=${best[$key,$module]:-}
      if [ -z "$old" ] || awk -v a="${line%% *}" -v b="${old%% *}" 'BEGIN { exit !(a < b) }'; then
        best[$key,$module]=$line
      fi
    done
  done
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%.2f", a / b; else print "-" }'; }

echo "gpdr module $(PYTHONPATH="$gpdr_path" "$python" -c 'import gpdr; print(gpdr.__version__)')" \
  "(threads=1) against the triangle package; fastest of $repeats runs each"
echo
echo "| input | opts | triangles | triangle s | gpdr s | gpdr / triangle | triangle peak MiB | gpdr peak MiB | triangle call MiB | gpdr call MiB |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
row() {
  local key=$1 label=$2 opts=$3
  read -r ts tp tc tn <<<"${best[$key,triangle]}"
  read -r gs gp gc gn <<<"${best[$key,gpdr]}"
  echo "| $label | '$opts' | $gn | $ts | $gs | $(ratio "$gs" "$ts") | $tp | $gp | $tc | $gc |"
}
measure_all delaunay random "$points" ""
row delaunay "$points random points" ""
measure_all quality random "$points" "q"
row quality "$points random points" "q"
measure_all pipe pipe "$pipe" "$pipe_switches"
row pipe "pipe.poly" "$pipe_switches"

echo
echo "Two Python threads, each meshing its own $points random points with '':"
echo
echo "| module | in a row s | threads at once s | threads / in a row | processes at once s | processes / in a row | peak MiB, threads at once |"
echo "|---|---:|---:|---:|---:|---:|---:|"
measure_all row in-a-row "$points"
measure_all together together "$points"
measure_all processes processes "$points"
for module in triangle gpdr; do
  read -r rs _ _ _ <<<"${best[row,$module]}"
  read -r ts tp _ _ <<<"${best[together,$module]}"
  read -r ps _ _ _ <<<"${best[processes,$module]}"
  echo "| $module | $rs | $ts | $(ratio "$ts" "$rs") | $ps | $(ratio "$ps" "$rs") | $tp |"
done
echo
echo "Processes at once: the same two calls in two processes, the machine's own floor"
echo "(shared cores, caches and memory bandwidth) under any two-thread speed-up."

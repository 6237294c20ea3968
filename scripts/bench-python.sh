#!/usr/bin/env bash
# gpdr's Python module against the triangle package (Triangle 1.6 inside a
# Cython wrapper), on the same inputs:
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
# Times: one interpreter per input imports both modules and calls them in
# turn, REPEATS times (default 5); the table gives each one's fastest call
# and the median of the REPEATS ratios of neighbouring calls, so that a
# change of the machine's load mid-run touches both sides of a ratio alike.
# The threads table alternates in a row, threads at once and processes at
# once the same way.  Peak memory: a fresh interpreter per module and input,
# one call (ru_maxrss; "call" is the growth over the peak before the call).
#
# Environment: GPDR_PYTHONPATH (default build/python: the module assembled
# by `cmake --build build --target gpdr_python`), PYTHON (default
# /usr/bin/python3), BENCH_DIR (default /tmp/gpdr-bench), REPEATS, POINTS
# (default 1000000), PIPE_SWITCHES (default pq20a0.01).  Figures are for
# comparing as ratios within one run of the script: these machines are
# small and noisy.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
python=${PYTHON:-/usr/bin/python3}
bench_dir=${BENCH_DIR:-/tmp/gpdr-bench}
gpdr_path=${GPDR_PYTHONPATH:-$root/build/python}
repeats=${REPEATS:-5}
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
# start from the same numpy arrays.
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
"""The measurements of scripts/bench-python.sh:

  time INPUT OPTS REPEATS         both modules in turn: 'triangle_s gpdr_s median_ratio triangles'
  memory MODULE INPUT OPTS        one call: 'peak_MiB call_MiB'
  threads MODULE POINTS REPEATS   'row_s threads_s processes_s threads/row processes/row'

INPUT is a number of random points or a .npz file of arrays.  gpdr runs
with threads=1 throughout.
"""
import importlib
import multiprocessing
import resource
import statistics
import sys
import threading
import time

import numpy as np


def load(name):
    module = importlib.import_module(name)
    extras = {"threads": 1} if name == "gpdr" else {}
    return lambda tri, opts="": module.triangulate(tri, opts, **extras)


def random_points(seed, count):
    return np.random.default_rng(seed).random((count, 2))


def read_input(spec):
    if spec.endswith(".npz"):
        return dict(np.load(spec))
    return {"vertices": random_points(1, int(spec))}


def peak_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def timed(call, *args):
    start = time.perf_counter()
    result = call(*args)
    return time.perf_counter() - start, result


def measure_time(spec, opts, repeats):
    tri = read_input(spec)
    meshers = {name: load(name) for name in ("triangle", "gpdr")}
    times = {name: [] for name in meshers}
    for r in range(repeats):
        order = ("triangle", "gpdr") if r % 2 == 0 else ("gpdr", "triangle")
        for name in order:
            seconds, mesh = timed(meshers[name], tri, opts)
            times[name].append(seconds)
            count = len(mesh["triangles"])
            del mesh
    ratios = [g / t for g, t in zip(times["gpdr"], times["triangle"])]
    print(f"{min(times['triangle']):.3f} {min(times['gpdr']):.3f} "
          f"{statistics.median(ratios):.2f} {count}")


def measure_memory(name, spec, opts):
    mesh = load(name)
    tri = read_input(spec)
    before = peak_mib()
    result = mesh(tri, opts)
    print(f"{peak_mib():.0f} {peak_mib() - before:.0f}")


def measure_threads(name, count, repeats):
    mesh = load(name)
    sets = [random_points(seed, count) for seed in (1, 2)]

    def in_a_row():
        for points in sets:
            mesh({"vertices": points})

    def threads_at_once():
        workers = [threading.Thread(target=mesh, args=({"vertices": p},)) for p in sets]
        for w in workers:
            w.start()
        for w in workers:
            w.join()

    def child(points, barrier, spans):
        barrier.wait()
        start = time.perf_counter()  # CLOCK_MONOTONIC: one clock for every process
        mesh({"vertices": points})
        spans.put((start, time.perf_counter()))

    def processes_at_once():
        context = multiprocessing.get_context("fork")
        barrier, spans = context.Barrier(2), context.Queue()
        children = [context.Process(target=child, args=(p, barrier, spans)) for p in sets]
        for c in children:
            c.start()
        got = [spans.get() for _ in children]
        for c in children:
            c.join()
        return max(end for _, end in got) - min(start for start, _ in got)

    rows, together, apart = [], [], []
    for _ in range(repeats):
        rows.append(timed(in_a_row)[0])
        together.append(timed(threads_at_once)[0])
        apart.append(processes_at_once())
    print(f"{min(rows):.3f} {min(together):.3f} {min(apart):.3f} "
          f"{statistics.median(t / r for t, r in zip(together, rows)):.2f} "
          f"{statistics.median(p / r for p, r in zip(apart, rows)):.2f}")


if __name__ == "__main__":
    what, args = sys.argv[1], sys.argv[2:]
    if what == "time":
        measure_time(args[0], args[1], int(args[2]))
    elif what == "memory":
        measure_memory(args[0], args[1], args[2])
    else:
        measure_threads(args[0], int(args[1]), int(args[2]))
PY

# run [ARG ...]: the driver with both modules importable.
run() {
  PYTHONPATH="$package:$gpdr_path" "$python" "$driver" "$@" 2>"$bench_dir/driver.log" || {
    echo "bench-python: $*: $(tail -1 "$bench_dir/driver.log")" >&2
    echo "- - - - -"
  }
}

echo "gpdr module $(PYTHONPATH="$gpdr_path" "$python" -c 'import gpdr; print(gpdr.__version__)')" \
  "(threads=1) against the triangle package; $repeats calls each, in turn"
echo
echo "| input | opts | triangles | triangle s | gpdr s | gpdr / triangle | triangle peak MiB | gpdr peak MiB | triangle call MiB | gpdr call MiB |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
row() {
  local label=$1 spec=$2 opts=$3 ts gs ratio count tp tc gp gc
  read -r ts gs ratio count <<<"$(run time "$spec" "$opts" "$repeats")"
  read -r tp tc <<<"$(run memory triangle "$spec" "$opts")"
  read -r gp gc <<<"$(run memory gpdr "$spec" "$opts")"
  echo "| $label | '$opts' | $count | $ts | $gs | $ratio | $tp | $gp | $tc | $gc |"
}
row "$points random points" "$points" ""
row "$points random points" "$points" "q"
row "pipe.poly" "$pipe" "$pipe_switches"

echo
echo "Two Python threads, each meshing its own $points random points with '':"
echo
echo "| module | in a row s | threads at once s | threads / in a row | processes at once s | processes / in a row |"
echo "|---|---:|---:|---:|---:|---:|"
for module in triangle gpdr; do
  read -r rs ts ps tr pr <<<"$(run threads "$module" "$points" "$repeats")"
  echo "| $module | $rs | $ts | $tr | $ps | $pr |"
done
echo
echo "Times: each side's fastest call; ratios: the median of neighbouring calls' ratios."
echo "Processes at once: the same two calls in two processes, the machine's own floor"
echo "(shared cores, caches and memory bandwidth) under any two-thread speed-up."

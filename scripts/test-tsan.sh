#!/bin/sh
# Builds gpdr's parallel tests and the gpdr program with ThreadSanitizer
# (build-tsan) and runs them: the parallel tests, then gpdr -j4 refining a
# sample, taking its -V statistics and writing every output file side by
# side, triangulating 220,000 points in bands, and refining a sample with vertex attributes (on four threads and on two: the same
# files), then eight threads calling libtriangle's triangulate() at once.  Any race report fails the run.  GCC 12 gives false warnings in
# Catch2's headers under sanitizers, so -Werror is off here.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-tsan"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGPDR_TSAN=ON -DGPDR_WERROR=OFF >/dev/null
cmake --build "$build" --target test_parallel gpdr_app capi_threads_test -j"${JOBS:-2}"
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
# Some kernels place memory where TSan cannot map it: run without ASLR where
# setarch can turn it off.
run() {
    if command -v setarch >/dev/null 2>&1; then
        setarch "$(uname -m)" -R "$@"
    else
        "$@"
    fi
}
run "$build/tests/test_parallel" "$@"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp "$root/poly-samples/flow.poly" "$scratch/"
# -V: the quality statistics of its 26,000 triangles are taken on four
# threads too (runs of 16384 triangles).
run "$build/gpdr" -Vpq30a0.02cenvj4 "$scratch/flow.poly" >/dev/null
# With a vertex attribute, which worker threads interpolate into the rows
# beside the mesh as they insert vertices, and read back for each other's.
# On four threads and on two, which must write the same files (each run in
# a folder of its own, the input named alike: the files' last line names it).
for threads in 4 2; do
    mkdir "$scratch/j$threads"
    cp "$root/tests/data/letter.poly" "$scratch/j$threads/"
    (cd "$scratch/j$threads" && run "$build/gpdr" -Qpq30a0.001j$threads letter.poly)
done
echo "gpdr -j4 and -j2 under ThreadSanitizer: no race reported"
for f in node ele poly; do cmp "$scratch/j2/letter.1.$f" "$scratch/j4/letter.1.$f"; done
echo "gpdr -j2 and -j4 under ThreadSanitizer: the same files"
# A point set large enough to be triangulated in bands on several threads
# (triangulate/strip_inserter.hpp), on four threads and on two: the same files.
awk 'BEGIN { srand(5); n = 220000; print n, 2, 0, 0;
  for (i = 1; i <= n; i++) printf "%d %.17g %.17g\n", i, rand(), rand() }' >"$scratch/points.node"
for threads in 4 2; do
    mkdir "$scratch/p$threads"
    cp "$scratch/points.node" "$scratch/p$threads/"
    (cd "$scratch/p$threads" && run "$build/gpdr" -Qj$threads points.node)
done
cmp "$scratch/p2/points.1.ele" "$scratch/p4/points.1.ele"
echo "gpdr's Delaunay in bands on -j4 and -j2 under ThreadSanitizer: no race, the same files"
# On a terminal: the progress line's thread reads the refining mesh's vertex
# count and the files written, while four threads refine and then write
# the files for other programs side by side (what the terminal shows is
# printed: a race report would be on it).  Its 82,000 triangles are more
# than one piece of the picture's pass over them, which the four threads
# share.
run python3 "$root/scripts/on-terminal.py" --show "$build/gpdr" -pq30a0.006cj4 --vtk --gmsh --svg \
    "$scratch/flow.poly"
echo "gpdr -j4 on a terminal (progress line) under ThreadSanitizer: no race reported"
run "$build/tests/capi_threads_test" >/dev/null
echo "libtriangle from 8 threads under ThreadSanitizer: no race reported"

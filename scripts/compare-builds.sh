#!/usr/bin/env bash
# Whether two builds of gpdr write the same bytes: every sample of
# poly-samples/ and tests/data/ (and the models of tests/data/models/) meshed
# by both under a set of switch sets at -j1 and -j2, every output file
# compared, then a few larger meshes.  For changes that must not change the
# output (restructuring, speed work).
#
#   scripts/compare-builds.sh OLD_GPDR [NEW_GPDR]     NEW_GPDR: build/gpdr
#
# Prints one line per run that differs (and the first differing file), then
# a summary; exits 1 when anything differs.  WORK names the scratch folder
# (default: a new one under /tmp, removed at the end).  The graded runs load
# poly-samples/grading.c compiled here (-u); -ra runs refine each first mesh
# with an .area file that halves the bound of every other triangle.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(realpath "${1:?usage: compare-builds.sh OLD_GPDR [NEW_GPDR]}")
new=$(realpath "${2:-$root/build/gpdr}")
work=${WORK:-$(mktemp -d)}
keep=${WORK:+yes}
trap '[ -n "$keep" ] || rm -rf "$work"' EXIT
mkdir -p "$work"
cc -O2 -shared -fPIC -DGRADING_C=0.05 -o "$work/grading.so" "$root/poly-samples/grading.c" -lm

# Switch sets for .poly inputs ("AREA" becomes a bound giving a few thousand
# triangles: the bounding box's area over 3,000) and for .node inputs.
poly_sets=(-pq -pq30 -pq33 -pq34 "-paAREA" "-pq33aAREA" "-pq25aAREA -e -n -v"
  "-pcAq28 -o2" "-pDq -e" "-pYq30aAREA" "-pq20aAREA --vtk --gmsh --svg" "-pq30aAREA -P0"
  "-pq30aAREA -P2")
node_sets=("" -q -q30 "-qaAREA -e -n -v" "-c -q25")
inputs=("$root"/poly-samples/*.poly "$root"/tests/data/*.poly "$root"/tests/data/models/*.poly
  "$root"/poly-samples/points.node "$root"/tests/data/*.node)

runs=0
differ=0
# mesh DIR PROGRAM SWITCHES FILE: runs PROGRAM in DIR on a copy of FILE,
# named gpdr (the files record the command line, the program's name too).
mesh() {
  (cd "$1" && exec -a gpdr "$2" -Q $3 "$4" >/dev/null 2>"$1/.stderr") || echo "exit $?" >>"$1/.stderr"
}
compare() {  # LABEL: compares the two folders
  runs=$((runs + 1))
  local a="$work/old" b="$work/new" f
  for f in $(cd "$a" && ls -A) $(cd "$b" && ls -A); do
    if ! cmp -s "$a/$f" "$b/$f"; then
      echo "differs: $1 ($f)"
      differ=$((differ + 1))
      return
    fi
  done
}

# both INPUT SWITCHES THREADS [AREA]: meshes a copy of INPUT with each
# build, in $work/old and $work/new, and compares the folders.  With AREA,
# each first mesh is refined again with an .area file that halves the
# bound of every other triangle (-ra).
both() {
  local input=$1 switches=$2 threads=$3 area=${4:-}
  local name base side program
  name=$(basename "$input")
  base=${name%.*}
  for side in old new; do
    rm -rf "${work:?}/$side"
    mkdir -p "$work/$side"
    cp "$input" "$work/$side/"
    program=$old
    [ $side = new ] && program=$new
    mesh "$work/$side" "$program" "$switches -j$threads" "$name"
    if [ -n "$area" ] && [ -f "$work/$side/$base.1.ele" ]; then
      awk 'NR == 1 { print $1; next } /^#/ { next } { print $1, (NR % 2 ? -1 : 1) * 0.5 * '"$area"' }' \
        "$work/$side/$base.1.ele" >"$work/$side/$base.1.area"
      mesh "$work/$side" "$program" "-rpq30a -j$threads" "$base.1"
    fi
  done
  compare "$name $switches -j$threads"
}

for input in "${inputs[@]}"; do
  name=$(basename "$input")
  case $name in
    *.poly) sets=("${poly_sets[@]}" "-pq20u") ;;
    *) sets=("${node_sets[@]}") ;;
  esac
  # The bounding box's area over 3,000, from the vertices of the file.
  area=$(awk 'NR == 1 || /^[[:space:]]*#/ || NF < 3 { next }
    { if (!n++) { x0 = x1 = $2; y0 = y1 = $3 }
      x0 = $2 < x0 ? $2 : x0; x1 = $2 > x1 ? $2 : x1; y0 = $3 < y0 ? $3 : y0; y1 = $3 > y1 ? $3 : y1 }
    END { printf "%.3g", (x1 - x0) * (y1 - y0) / 3000 }' "$input")
  for set in "${sets[@]}"; do
    switches=${set//AREA/$area}
    [ "$set" = "-pq20u" ] && switches="-pq20 --unsuitable $work/grading.so"
    refine_area=""
    [ "$set" = "-paAREA" ] && refine_area=$area
    for threads in 1 2; do both "$input" "$switches" "$threads" "$refine_area"; done
  done
done
# Larger meshes, where the quadtree's leaves split and many rounds run: the
# graded pipe at c = 1e-3 (1.5 million triangles) and area bounds at 30 and
# 33 degrees.
cc -O2 -shared -fPIC -DGRADING_C=1e-3 -o "$work/graded.so" "$root/poly-samples/grading.c" -lm
# And the Delaunay triangulation of 300,000 random points.
awk 'BEGIN { srand(7); n = 300000; print n, 2, 0, 0;
  for (i = 1; i <= n; i++) printf "%d %.17g %.17g\n", i, rand(), rand() }' >"$work/random.node"
large=("pipe.poly|-pq20 --unsuitable $work/graded.so" "flow.poly|-pq30a2e-4"
  "flow.poly|-pq33a5e-4 -e -n" "pipe.poly|-pq25a2" "random.node|-e" "random.node|-q")
for run in "${large[@]}"; do
  name=${run%%|*}
  source_file=$root/poly-samples/$name
  [ "$name" = random.node ] && source_file=$work/random.node
  for threads in 1 2; do both "$source_file" "${run#*|}" "$threads"; done
done
echo "compare-builds: $runs runs, $differ with different files ($old against $new)"
[ "$differ" -eq 0 ]

#!/usr/bin/env bash
# Writing the graded pipe (the mesh of scripts/bench-graded.sh) in each
# output format: Triangle's .node and .ele beside --vtk's .vtu, --gmsh's .msh
# and --svg's picture, in seconds and MB.  Then the cost of the progress line
# (gpdr on a terminal) on the whole graded run.
#
#   scripts/bench-formats.sh                  c = 1e-4, about 15 million triangles
#   GRADING_C=1e-3 scripts/bench-formats.sh   a smaller pipe (about 1.5 million)
#   ROUNDS=3 THREADS=2 scripts/bench-formats.sh
#
# The pipe is meshed once (-pq20, the grading plug-in, THREADS threads,
# default 2); every file is then written from that mesh read back with -rp,
# one format per run on one thread (-j1), so each row is one file's
# "Output milliseconds" (-V) alone; the rounds are interleaved and each
# row ends with the median and its ratio to the .ele file's median.
#
# The progress line: the graded run again, with standard error on a
# pseudo-terminal (the line shows) and in a file (it does not), alternating,
# ROUNDS times each; the whole run's wall time.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
c=${GRADING_C:-1e-4}
threads=${THREADS:-2}
rounds=${ROUNDS:-3}
input=$(bench_input "$root/poly-samples/pipe.poly")
dir=$(dirname "$input")
lib="$BENCH_DIR/grading-$c.so"
cc -O2 -shared -fPIC "-DGRADING_C=$c" -o "$lib" "$root/poly-samples/grading.c" -lm

rm -f "$dir"/pipe.1.* "$dir"/pipe.2.*
(cd "$dir" && "$GPDR" -Vpq20j"$threads" --unsuitable "$lib" pipe.poly >"$BENCH_DIR/mesh.log")
triangles=$(count "$BENCH_DIR/mesh.log" "Mesh triangles:")
echo "Graded pipe, -q20, c = $c: $triangles triangles (meshed once on $threads threads)"
echo

# write_one SWITCHES FILE: writes pipe.2.FILE from the mesh; prints "seconds MB".
write_one() {
  local switches=$1 file=$2
  rm -f "$dir"/pipe.2.*
  sync
  (cd "$dir" && "$GPDR" -rpVj1 $switches pipe.1 >"$BENCH_DIR/format.log" 2>&1)
  local bytes
  bytes=$(stat -c %s "$dir/pipe.2.$file")
  echo "$(ms "$BENCH_DIR/format.log" "Output") $(awk -v b="$bytes" 'BEGIN { printf "%.1f", b / 1e6 }')"
}

names=(".node" ".ele" ".vtu (--vtk)" ".msh (--gmsh)" ".svg (--svg)")
switches=("-EP" "-NP" "-NEP --vtk" "-NEP --gmsh" "-NEP --svg")
files=(node ele vtu msh svg)
declare -A seconds mb
for round in $(seq "$rounds"); do
  for i in "${!names[@]}"; do
    read -r s m < <(write_one "${switches[$i]}" "${files[$i]}")
    seconds[$i]="${seconds[$i]:-} $s"
    mb[$i]=$m
  done
done
median() { tr ' ' '\n' | awk 'NF' | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }
ele_median=$(echo "${seconds[1]}" | median)
echo "| file | switches | write s (each round) | median s | vs .ele | MB |"
echo "|---|---|---|---:|---:|---:|"
for i in "${!names[@]}"; do
  m=$(echo "${seconds[$i]}" | median)
  echo "| ${names[$i]} | ${switches[$i]} |${seconds[$i]} | $m | $(awk -v a="$m" -v b="$ele_median" 'BEGIN { printf "%.2f", a / b }') | ${mb[$i]} |"
done
rm -f "$dir"/pipe.2.*

# The progress line's cost: the same graded run with standard error on a
# terminal and in a file, both started the same way (scripts/on-terminal.py
# gives each a terminal; one then sends standard error to a file), timed
# from the start to the exit.
echo
# Not -Q, which turns the line off: both runs print the same (-V on standard
# output), only standard error differs.
graded=("$GPDR" -Vpq20j"$threads" -NEP --unsuitable "$lib" pipe.poly)
timed_run() {  # STDERR (terminal, or a file name) COMMAND...: prints the wall seconds
  local where=$1
  shift
  local redirect=()
  [ "$where" = terminal ] || redirect=(--stderr "$where")
  (cd "$dir" && python3 "$root/scripts/on-terminal.py" --time "${redirect[@]}" "$@" 2>&1 >/dev/null)
}
terminal="" file=""
for round in $(seq "$rounds"); do
  terminal="$terminal $(timed_run terminal "${graded[@]}")"
  file="$file $(timed_run "$BENCH_DIR/stderr.log" "${graded[@]}")"
done
t=$(echo "$terminal" | median)
f=$(echo "$file" | median)
echo "| graded run, -NEP | wall s (each round) | median s | vs no line |"
echo "|---|---|---:|---:|"
echo "| stderr on a terminal (progress line) |$terminal | $t | $(awk -v a="$t" -v b="$f" 'BEGIN { printf "%.3f", a / b }') |"
echo "| stderr in a file (no line) |$file | $f | 1.000 |"

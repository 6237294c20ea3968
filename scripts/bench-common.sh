# Shared by the benchmark scripts (source it).  Runs gpdr and, when the
# environment names one, a Triangle binary (TRIANGLE=/path/to/triangle) on the
# same input, and prints one Markdown table row per run: stage times taken
# from each program's -V "... milliseconds" lines, wall time and peak memory
# from /usr/bin/time.  Figures are meant to be compared as ratios within one
# run of a script: these machines are small and noisy.

GPDR=${GPDR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build/gpdr}
BENCH_DIR=${BENCH_DIR:-/tmp/gpdr-bench}
mkdir -p "$BENCH_DIR"

# The programs run from their input's folder: make relative paths absolute.
absolute_program() {
  case $1 in
    */*) echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" ;;
    *) echo "$1" ;;
  esac
}
GPDR=$(absolute_program "$GPDR")
if [ -n "${TRIANGLE:-}" ]; then TRIANGLE=$(absolute_program "$TRIANGLE"); fi
if [ -n "${TRIANGLE_GRADED:-}" ]; then TRIANGLE_GRADED=$(absolute_program "$TRIANGLE_GRADED"); fi

if [ ! -x /usr/bin/time ]; then
  echo "bench: installing the 'time' package for peak-memory figures" >&2
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq time >/dev/null
fi

# random_points N FILE: N uniform random points in the unit square (fixed seed).
random_points() {
  [ -f "$2" ] && return
  awk -v n="$1" 'BEGIN { srand(12345); print n, 2, 0, 0;
    for (i = 1; i <= n; i++) printf "%d %.17g %.17g\n", i, rand(), rand() }' >"$2"
}

bench_header() {
  echo "| input | program | switches | vertices | triangles | read+tri s | refine s | write s | total s | peak MiB |"
  echo "|---|---|---|---:|---:|---:|---:|---:|---:|---:|"
}

# ms LOG NAME: the number on the line "NAME milliseconds: N" (0 if absent).
ms() { awk -v k="$2 milliseconds:" 'index($0, k) { v = $NF } END { printf "%.3f", (v == "" ? 0 : v) / 1000 }' "$1"; }
count() { awk -v k="$2" 'index($0, k) { v = $NF } END { print (v == "" ? "?" : v) }' "$1"; }

# bench_run LABEL PROGRAM SWITCHES INPUT [ARG ...]: runs PROGRAM -VSWITCHES [ARG ...] INPUT
# in the input's folder (so keep inputs in $BENCH_DIR: the outputs land beside
# them).  The ARGs are extra arguments such as gpdr's --unsuitable LIB.so.
bench_run() {
  local label=$1 program=$2 switches=$3 input=$4
  shift 4
  local log="$BENCH_DIR/run.log" tlog="$BENCH_DIR/time.log"
  # Every program starts alike: no earlier result to replace (freeing a
  # gigabyte of page cache at the rename would count as its output time)
  # and no write-back of the previous run's files going on.
  local stem="${input%.*}"
  rm -f "$stem".1.*
  sync
  ( cd "$(dirname "$input")" && /usr/bin/time -f "%e %M" -o "$tlog" "$program" "-V$switches" "$@" "$(basename "$input")" >"$log" 2>&1 ) || {
    echo "| $(basename "$input") | $label | -$switches | failed: $(tail -1 "$log") |"; return; }
  local wall peak
  read -r wall peak <"$tlog"
  # Triangle: Delaunay + Segment + Hole; gpdr: Read + Delaunay (points) or Mesh (-p).
  local tri_ms dl seg hole mesh
  dl=$(ms "$log" "Delaunay"); seg=$(ms "$log" "Segment"); hole=$(ms "$log" "Hole"); tri_ms=$(ms "$log" "Read")
  mesh=$(ms "$log" "Mesh")
  local pre
  pre=$(awk -v a="$dl" -v b="$seg" -v c="$hole" -v d="$tri_ms" -v e="$mesh" 'BEGIN { printf "%.3f", a + b + c + d + e }')
  echo "| $(basename "$input") | $label | -$switches | $(count "$log" "Mesh vertices:") | $(count "$log" "Mesh triangles:") | $pre | $(ms "$log" "Quality") | $(ms "$log" "Output") | $wall | $((peak / 1024)) |"
}

# bench_input FILE: copies FILE into $BENCH_DIR (if not there yet) and prints
# the copy's path, so that runs never write beside the repository's samples.
bench_input() {
  local copy
  copy="$BENCH_DIR/$(basename "$1")"
  cp -f "$1" "$copy"
  echo "$copy"
}

# ele_count FILE: the triangle count in an .ele file's header.
ele_count() { awk '{ sub(/#.*/, "") } NF { print $1; exit }' "$1"; }

# bench_sample PROGRAM SWITCHES INPUT: runs PROGRAM -VSWITCHES INPUT in the
# input's folder, as bench_run does, and prints one line of figures:
# "read_ms delaunay_ms total_ms wall_s peak_kib" ("failed" if it failed).
# read_ms is gpdr's "Read milliseconds"; Triangle does not time its reading
# apart, so for a program without that line it is the total running time
# less the Delaunay and output times (Triangle then does nothing else).
bench_sample() {
  local program=$1 switches=$2 input=$3
  local log="$BENCH_DIR/run.log" tlog="$BENCH_DIR/time.log"
  rm -f "${input%.*}".1.*
  sync
  ( cd "$(dirname "$input")" && /usr/bin/time -f "%e %M" -o "$tlog" "$program" "-V$switches" "$(basename "$input")" >"$log" 2>&1 ) || {
    echo failed; return; }
  local wall peak
  read -r wall peak <"$tlog"
  awk -v wall="$wall" -v peak="$peak" '
    /^Read milliseconds:/ { read = $NF; has_read = 1 }
    /^Delaunay milliseconds:/ { dl = $NF }
    /^Output milliseconds:/ { out = $NF }
    /^Total running milliseconds:/ { total = $NF }
    END { if (!has_read) read = total - dl - out
          printf "%d %d %d %s %d\n", read, dl, total, wall, peak }' "$log"
}

# median_columns FILE: the median of each column of FILE's lines of numbers
# (the lower middle one for an even count), space-separated.
median_columns() {
  local columns
  columns=$(awk 'NR == 1 { print NF }' "$1")
  for ((c = 1; c <= columns; c++)); do
    sort -g -k"$c","$c" "$1" | awk -v c="$c" '{ v[NR] = $c } END { printf "%s ", v[int((NR + 1) / 2)] }'
  done
  echo
}

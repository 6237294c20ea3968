#!/usr/bin/env bash
# Refinement time per triangle as the mesh grows: the graded pipe
# (poly-samples/pipe.poly, -pq20 with the grading function of
# poly-samples/grading.c) at several c, from about 1.5 to 260 million
# triangles, no files written.
#
#   scripts/bench-sizes.sh                 c = 1e-3 1e-4 3e-5 1e-5 5.7e-6, -j2, three rounds
#   SIZES="1e-3 1e-4" ROUNDS=5 THREADS=4 scripts/bench-sizes.sh
#
# Each round runs every size once, smallest first, so that every size meets
# the machine in the same mood; a size whose mesh would not fit in the
# memory available now (about 70 bytes a triangle, estimated from c) is
# left out with a note.  Per size: the median over the rounds of
# refinement's time ("Quality milliseconds", -V) over the triangle count,
# the spread of the rounds, and from /usr/bin/time the peak, the minor page
# faults and the system time of the median round.  The last column is the
# size's time per triangle over the smallest of the table; the line under
# the table gives the largest over the smallest.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
sizes=(${SIZES:-1e-3 1e-4 3e-5 1e-5 5.7e-6})
rounds=${ROUNDS:-3}
threads=${THREADS:-2}
input=$(bench_input "$root/poly-samples/pipe.poly")

# The pipe's triangle count is close to 1480 / c (1.47 million at 1e-3,
# 261 million at 5.7e-6).
fits() {
  local avail
  avail=$(awk '/MemAvailable/ { print $2 * 1024 }' /proc/meminfo)
  awk -v c="$1" -v a="$avail" 'BEGIN { exit !(1480 / c * 70 < a) }'
}

rows="$BENCH_DIR/sizes-rows.txt"
: >"$rows"
for c in "${sizes[@]}"; do
  cc -O2 -shared -fPIC "-DGRADING_C=$c" -o "$BENCH_DIR/grading-$c.so" "$root/poly-samples/grading.c" -lm
done

echo "Graded pipe, -pq20 -NEP -j$threads, $rounds rounds; $(nproc) cores, $(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo);" \
  "transparent huge pages: $(cat /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null || echo unknown)"
for round in $(seq "$rounds"); do
  for c in "${sizes[@]}"; do
    if ! fits "$c"; then
      [ "$round" = 1 ] && echo "c = $c left out: about $(awk -v c="$c" 'BEGIN { printf "%.0f", 1480 / c * 70 / 2^30 }') GiB needed"
      continue
    fi
    log="$BENCH_DIR/sizes-run.log"
    /usr/bin/time -f "%M %R %S %U %e" -o "$BENCH_DIR/sizes-time.log" \
      "$GPDR" "-pq20VNEPj$threads" "$input" --unsuitable "$BENCH_DIR/grading-$c.so" >"$log" 2>&1
    read -r peak faults sys user wall <"$BENCH_DIR/sizes-time.log"
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$c" "$round" "$(count "$log" "Mesh triangles:")" \
      "$(ms "$log" Quality)" "$peak" "$faults" "$sys" "$user" "$wall" >>"$rows"
  done
done

echo
echo "| c | triangles | refinement s (rounds) | ns a triangle (median) | peak MiB | minor faults | system s / user s | vs fastest |"
echo "|---|---:|---|---:|---:|---:|---|---:|"
awk -F'\t' '
  { n[$1]++; k = n[$1]; tri[$1] = $3; q[$1, k] = $4; rest[$1, k] = $5 "\t" $6 "\t" $7 "\t" $8
    if (!($1 in seen)) { seen[$1] = 1; order[++m] = $1 } }
  END {
    for (i = 1; i <= m; i++) {
      c = order[i]; r = n[c]
      # the median round: sort the round numbers by time
      for (a = 1; a <= r; a++) idx[a] = a
      for (a = 1; a <= r; a++) for (b = a + 1; b <= r; b++)
        if (q[c, idx[b]] < q[c, idx[a]]) { t = idx[a]; idx[a] = idx[b]; idx[b] = t }
      mid = idx[int((r + 1) / 2)]
      list = ""; for (a = 1; a <= r; a++) list = list (a > 1 ? " " : "") q[c, a]
      ns[c] = q[c, mid] * 1e9 / tri[c]; med[c] = q[c, mid]; line[c] = list; pick[c] = rest[c, mid]
      if (fastest == "" || ns[c] < fastest) fastest = ns[c]
      if (ns[c] > slowest) slowest = ns[c]
    }
    for (i = 1; i <= m; i++) {
      c = order[i]; split(pick[c], f, "\t")
      printf "| %s | %d | %s | %.0f | %.0f | %d | %s / %s | %.2f |\n", c, tri[c], line[c], ns[c],
        f[1] / 1024, f[2], f[3], f[4], ns[c] / fastest
    }
    printf "\nslowest / fastest time a triangle: %.2f\n", slowest / fastest
  }' "$rows"

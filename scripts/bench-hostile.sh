#!/usr/bin/env bash
# Hostile input: peak memory and wall time of gpdr refusing an input that is
# not a text file and never ends.  Five cases: /dev/zero as a .node file and
# /dev/urandom as a .poly file (-p), each named as the input (a symbolic link:
# gpdr, like Triangle, reads NAME.node for an input NAME without a known
# extension, so `gpdr /dev/zero` would look for /dev/zero.node), and each fed
# through a fifo by a writer that stops when gpdr closes its end; then an
# endless comment line through a fifo (refused past 1 MiB).  Every run
# must exit with status 1; the targets are a peak resident set below 64 MiB
# and under a second.  Prints a Markdown table.
#
#   scripts/bench-hostile.sh             GPDR=build/gpdr by default
#   GPDR=/path/to/gpdr scripts/bench-hostile.sh
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
target_mib=64
target_s=1

dir=$(mktemp -d "$BENCH_DIR/hostile.XXXXXX")
trap 'rm -rf "$dir"' EXIT

# run_case LABEL SWITCHES NAME KIND SOURCE: runs gpdr [SWITCHES] NAME in
# $dir, where NAME is a link to the file SOURCE (KIND=link) or a fifo that
# the shell command SOURCE writes into (KIND=fifo), and prints the table row.
run_case() {
  local label=$1 switches=$2 name=$3 kind=$4 source=$5 writer=""
  rm -f "$dir/$name"
  if [ "$kind" = link ]; then
    ln -s "$source" "$dir/$name"
  else
    mkfifo "$dir/$name"
    # The writer gets SIGPIPE when gpdr closes the fifo; the timeout only
    # matters if gpdr never opened it.
    timeout 60 sh -c "{ $source; } >\"\$1\"" sh "$dir/$name" 2>/dev/null &
    writer=$!
  fi
  local status=0
  (cd "$dir" && /usr/bin/time -f "%e %M" -o time.log "$GPDR" $switches "$name" >run.log 2>&1) ||
    status=$?
  if [ -n "$writer" ]; then
    kill "$writer" 2>/dev/null || true
    wait "$writer" 2>/dev/null || true
  fi
  local wall peak_kib peak_mib verdict
  read -r wall peak_kib < <(tail -n 1 "$dir/time.log")
  peak_mib=$(awk -v k="$peak_kib" 'BEGIN { printf "%.1f", k / 1024 }')
  verdict=$(awk -v m="$peak_mib" -v t="$wall" -v s="$status" -v tm="$target_mib" -v ts="$target_s" \
    'BEGIN { print (s == 1 && m < tm && t < ts) ? "yes" : "no" }')
  printf "| %s | \`gpdr %s\` | %s | %s | %s | %s | %s |\n" "$label" "${switches:+$switches }$name" \
    "$status" "$peak_mib" "$wall" "$verdict" "$(head -c 120 "$dir/run.log" | tr -d '\n')"
}

echo "gpdr: $GPDR"
echo
echo "| case | command | exit | peak MiB (< $target_mib) | wall s (< $target_s) | on target | message |"
echo "|---|---|---:|---:|---:|---|---|"
run_case "/dev/zero named" "" zero.node link /dev/zero
run_case "/dev/urandom named" "-p" urandom.poly link /dev/urandom
run_case "/dev/zero through a fifo" "" fifo.node fifo "cat /dev/zero"
run_case "/dev/urandom through a fifo" "-p" fifo.poly fifo "cat /dev/urandom"
run_case "an endless comment through a fifo" "" fifo.node fifo "printf '#'; tr '\\0' x </dev/zero"

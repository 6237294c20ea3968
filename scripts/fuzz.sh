#!/usr/bin/env bash
# Fuzzes gpdr's readers and pipeline (tests/fuzz) for as long as asked, in
# the shared sanitizer build (build-asan, scripts/asan-build.sh).
#
#   scripts/fuzz.sh [TARGET|all] [SECONDS]     (defaults: all, 60 per target)
#
# Targets: node poly ele area mesh pipeline.  Each starts from its committed
# corpus (tests/fuzz/corpus/TARGET, never written to) and writes what it
# finds under $FUZZ_WORK (default build-asan/fuzz-work):
#   TARGET/corpus/   new inputs that reach new code (kept between runs, so a
#                    later run goes on from them; copy a good one into the
#                    committed corpus by hand)
#   TARGET/crashes/  an input that crashed, broke an invariant or timed out
#   TARGET/log       libFuzzer's output
# Extra libFuzzer flags go in FUZZ_ARGS (FUZZ_ARGS="-fork=2 -ignore_crashes=1"
# uses two processes and goes on after a crash).  Exits 1
# when a target found something.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
all=(node poly ele area mesh pipeline)
which=${1:-all}
seconds=${2:-60}
if [ "$which" = all ]; then
  targets=("${all[@]}")
elif [[ " ${all[*]} " == *" $which "* ]]; then
  targets=("$which")
else
  echo "fuzz.sh: unknown target '$which' (one of: ${all[*]}, all)" >&2
  exit 2
fi
work=${FUZZ_WORK:-$root/build-asan/fuzz-work}

"$root/scripts/asan-build.sh" "${targets[@]/#/fuzz_}"
export ASAN_OPTIONS="detect_leaks=1 ${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1 print_stacktrace=1 ${UBSAN_OPTIONS:-}"

found=0
for t in "${targets[@]}"; do
  dir="$work/$t"
  mkdir -p "$dir/corpus" "$dir/crashes"
  echo "fuzz.sh: $t for $seconds s (new inputs: $dir/corpus, crashes: $dir/crashes)"
  before=$(find "$dir/crashes" -type f | wc -l)
  # shellcheck disable=SC2086
  if "$root/build-asan/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$dir/crashes/" \
      ${FUZZ_ARGS:-} "$dir/corpus" "$root/tests/fuzz/corpus/$t" >"$dir/log" 2>&1; then
    status=ok
  else
    status=failed
  fi
  # With -ignore_crashes (fork mode) libFuzzer goes on and exits 0.
  new=$(($(find "$dir/crashes" -type f | wc -l) - before))
  if [ "$status" = failed ] || [ "$new" -gt 0 ]; then
    status="FOUND SOMETHING: $new new file(s) in $dir/crashes, see $dir/log"
    found=1
  fi
  # The run count: the final statistics, or fork mode's last "#N:" line.
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p; s/^#\([0-9]*\): cov.*/\1/p' \
    "$dir/log" | tail -1)
  echo "fuzz.sh: $t: ${runs:-?} runs, $status"
done
exit "$found"

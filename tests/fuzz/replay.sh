#!/bin/sh
# CTest's replay of one fuzz target: runs every input of the committed
# corpus, then fuzzes from a fixed seed for a fixed number of runs, with a
# time guard, so that the same build does the same work each time.  New
# inputs go to a scratch folder (libFuzzer writes into its first corpus
# folder), never into the committed corpus; a crash is saved there too.
#
#   replay.sh TARGET CORPUS SCRATCH RUNS SECONDS
set -eu
target=$1 corpus=$2 scratch=$3 runs=$4 seconds=$5
rm -rf "$scratch"
mkdir -p "$scratch/new" "$scratch/crashes"
exec "$target" -seed=1 -runs="$runs" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$scratch/crashes/" \
    "$scratch/new" "$corpus"

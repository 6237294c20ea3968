#!/usr/bin/env bash
# Sets up and builds gpdr (scripts/setup.sh), then runs the whole test suite:
# the Catch2 unit and CLI tests through CTest, and the parallel tests again in
# a ThreadSanitizer build.  This is what .ci/run runs.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh
jobs=${JOBS:-$(nproc)}
ctest --test-dir build --output-on-failure -j "$jobs"

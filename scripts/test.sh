#!/usr/bin/env bash
# Sets up and builds gpdr (scripts/setup.sh), then runs the whole test suite:
# the parallel tests under ThreadSanitizer, the library's C interface tests
# under AddressSanitizer, then the Catch2 unit and CLI tests and the C
# interface tests through CTest.  This is what .ci/run runs.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh
jobs=${JOBS:-$(nproc)}
# The parallel tests again under ThreadSanitizer (a build of their own in
# build-tsan), first, so that CTest's summary of the whole suite comes last.
scripts/test-tsan.sh
# The library's tests again under AddressSanitizer and LeakSanitizer
# (build-asan).
scripts/test-asan.sh
ctest --test-dir build --output-on-failure -j "$jobs"

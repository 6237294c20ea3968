#!/bin/sh
# Builds the tests that exercise gpdr as a library with AddressSanitizer,
# LeakSanitizer and UBSan (one shared clang build, build-asan, made by
# scripts/asan-build.sh) and runs them:
#   - the C interface's tests (capi/), which check that every array
#     libtriangle hands out is freed by trifree() and nothing else leaks,
#     and that no error path reads or writes out of bounds;
#   - the fuzz targets' replay (tests/fuzz): each target's committed corpus,
#     then a fixed number of fuzz runs from a fixed seed, a few seconds each.
#
# Tests join by adding their CTest name pattern and build targets below.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-asan"
tests='^(capi: (meshing|errors|threads|locale)|fuzz: .*)$'
targets="capi_meshing_test capi_errors_test capi_threads_test capi_locale_test
    fuzz_node fuzz_poly fuzz_ele fuzz_area fuzz_mesh fuzz_pipeline"
# shellcheck disable=SC2086
"$root/scripts/asan-build.sh" $targets
export ASAN_OPTIONS="detect_leaks=1 ${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1 print_stacktrace=1 ${UBSAN_OPTIONS:-}"
ctest --test-dir "$build" -R "$tests" --output-on-failure -j"${JOBS:-2}"
echo "library tests under AddressSanitizer: no error reported"

#!/bin/sh
# Builds the tests that exercise gpdr as a library with AddressSanitizer,
# LeakSanitizer and UBSan (one shared build, build-asan) and runs them: the
# C interface's tests (capi/), which check that every array libtriangle
# hands out is freed by trifree() and nothing else leaks, and that no error
# path reads or writes out of bounds.  GCC 12 gives false warnings in
# Catch2's headers under sanitizers, so -Werror is off here.
#
# Tests join by adding their CTest name pattern and build targets below.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-asan"
tests='^capi: (meshing|errors|threads|locale)$'
targets="capi_meshing_test capi_errors_test capi_threads_test capi_locale_test"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGPDR_SANITIZE=ON \
    -DGPDR_WERROR=OFF >/dev/null
# shellcheck disable=SC2086
cmake --build "$build" --target $targets -j"${JOBS:-2}"
export ASAN_OPTIONS="detect_leaks=1 ${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1 print_stacktrace=1 ${UBSAN_OPTIONS:-}"
ctest --test-dir "$build" -R "$tests" --output-on-failure -j"${JOBS:-2}"
echo "library tests under AddressSanitizer: no error reported"

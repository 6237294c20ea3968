#!/bin/sh
# Builds gpdr's parallel tests with ThreadSanitizer (build-tsan) and runs
# them; any race report fails the run.  GCC 12 gives false warnings in
# Catch2's headers under sanitizers, so -Werror is off here.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-tsan"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGPDR_TSAN=ON -DGPDR_WERROR=OFF >/dev/null
cmake --build "$build" --target test_parallel -j"${JOBS:-2}"
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
# Some kernels place memory where TSan cannot map it: run without ASLR where
# setarch can turn it off.
if command -v setarch >/dev/null 2>&1; then
    exec setarch "$(uname -m)" -R "$build/tests/test_parallel" "$@"
fi
exec "$build/tests/test_parallel" "$@"

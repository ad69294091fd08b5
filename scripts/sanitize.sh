#!/usr/bin/env bash
# make sanitize (docs/reliability.md): builds fpmshell and its tests with AddressSanitizer and
# UndefinedBehaviorSanitizer in $SANITIZE_BUILD (build-sanitize), runs the unit, io and fuzz
# replay tests there, then a short run of every example (a few dozen steps, 2 threads). Any
# sanitizer report fails the test or the run it occurs in, and the script exits 1.
set -euo pipefail
cd "$(dirname "$0")/.."

SANITIZE_BUILD=${SANITIZE_BUILD:-build-sanitize}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

scripts/install-deps.sh
cmake -S . -B "$SANITIZE_BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFPMSHELL_SANITIZE=ON \
    -DFPMSHELL_BENCHMARKS=OFF >/dev/null
cmake --build "$SANITIZE_BUILD" -j "$JOBS"
ctest --test-dir "$SANITIZE_BUILD" -L '^(unit|io|fuzz)$' --output-on-failure -j "$JOBS"

# A short run of every example (40 steps, 2 threads)
scripts/short_example_runs.sh "$SANITIZE_BUILD/fpmshell" "$SANITIZE_BUILD/sanitize_runs"
echo "sanitize: every test and example run passed under AddressSanitizer and UBSan"

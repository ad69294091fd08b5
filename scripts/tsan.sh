#!/usr/bin/env bash
# make tsan (docs/reliability.md): builds fpmshell and its tests with clang and ThreadSanitizer
# in $TSAN_BUILD (build-tsan), then runs the unit tests (those of the parallel loops run on 1, 2
# and all threads) and a short 2-thread run of every example. OpenMP is clang's libomp, whose
# barriers and tasks ThreadSanitizer learns of through libarcher (OMP_TOOL_LIBRARIES). A data
# race fails the test or the run it occurs in, and the script exits 1.
set -euo pipefail
cd "$(dirname "$0")/.."

TSAN_BUILD=${TSAN_BUILD:-build-tsan}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
scripts/install-deps.sh clang libomp-dev
archer=$(ls /usr/lib/llvm-*/lib/libarcher.so 2>/dev/null | sort -V | tail -1)
[[ -n "$archer" ]] || { echo "tsan: libarcher.so not found (Debian package libomp-dev)" >&2; exit 1; }
export OMP_TOOL_LIBRARIES=$archer
# ignore_noninstrumented_modules: libomp itself is not instrumented, and its own bookkeeping
# (the buffers of a dynamic schedule, allocated by one thread and freed by another after
# libomp's own barrier) reads as races through the memset and malloc interceptors; libarcher
# asks for this setting. Our code is instrumented: its accesses are all still checked.
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1}
export OMP_NUM_THREADS=2

cmake -S . -B "$TSAN_BUILD" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DFPMSHELL_TSAN=ON -DFPMSHELL_BENCHMARKS=OFF -DFPMSHELL_MPI=OFF >/dev/null
cmake --build "$TSAN_BUILD" -j "$JOBS"
ctest --test-dir "$TSAN_BUILD" -L '^unit$' --output-on-failure -j "$JOBS"
scripts/short_example_runs.sh "$TSAN_BUILD/fpmshell" "$TSAN_BUILD/tsan_runs"
echo "tsan: every unit test and example run passed under ThreadSanitizer"

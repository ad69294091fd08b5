#!/usr/bin/env bash
# make sanitize (README "Reliability"): builds fpmshell and its tests with AddressSanitizer and
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

# A short run of every example: set-up, element and contact loops, output and the restart file
# of its first steps, 40 stable steps long (check prints the stable step).
out="$SANITIZE_BUILD/sanitize_runs"
rm -rf "$out"
for model in examples/*/model.yaml; do
    name=$(basename "$(dirname "$model")")
    dt=$("$SANITIZE_BUILD/fpmshell" check "$model" | sed -n 's/.*stable time step *\([0-9.eE+-]*\).*/\1/p' | head -1)
    [[ -n "$dt" ]] || { echo "sanitize: no stable step in the summary of $model" >&2; exit 1; }
    end=$(python3 -c "print(40 * $dt)")
    echo "sanitize: $name, 40 steps (end_time $end)"
    "$SANITIZE_BUILD/fpmshell" run "$model" -o "$out/$name" --quiet --threads 2 \
        --restart-every 1e9 --set "control.end_time=$end" --set "output.every=0" >/dev/null 2>"$out.$name.err" ||
        { cat "$out.$name.err" >&2; echo "sanitize: the run of $model failed" >&2; exit 1; }
done
echo "sanitize: every test and example run passed under AddressSanitizer and UBSan"

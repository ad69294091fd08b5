#!/usr/bin/env bash
# make fuzz (docs/reliability.md): builds the fuzz targets of fuzz/ with clang, libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer in $FUZZ_BUILD (build-fuzz), writes their seed
# corpora, and runs every target for FUZZ_SECONDS seconds (default 60), FUZZ_JOBS at a time
# (default: the number of cores). A crash, a sanitizer report, a leak, an exception other than
# an input error, or an input that takes longer than 10 s (a hang) fails the target: its input
# is kept in $FUZZ_BUILD/findings/<target>/ and the script exits 1. Each target's corpus grows in
# $FUZZ_BUILD/corpus/<target>/ from run to run; $FUZZ_BUILD/fuzz_report.txt gets a line per
# target: executions, seconds, corpus size, result.
#
# To keep an input that failed as a regression test once its cause is fixed: copy it to
# fuzz/regressions/<target>/ (make test replays that folder through the target).
set -euo pipefail
cd "$(dirname "$0")/.."

FUZZ_SECONDS=${FUZZ_SECONDS:-60}
FUZZ_BUILD=${FUZZ_BUILD:-build-fuzz}
FUZZ_JOBS=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}
TARGETS=(model_yaml set_overrides gmsh_msh abaqus_inp lsdyna_k restart_file)
if [[ -n "${FUZZ_TARGETS:-}" ]]; then read -r -a TARGETS <<< "$FUZZ_TARGETS"; fi

scripts/install-deps.sh clang libclang-rt-dev
cmake -S . -B "$FUZZ_BUILD" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DFPMSHELL_FUZZ=ON -DFPMSHELL_TESTS=OFF -DFPMSHELL_BENCHMARKS=OFF -DFPMSHELL_OPENMP=OFF \
    -DFPMSHELL_MPI=OFF >/dev/null
cmake --build "$FUZZ_BUILD" -j "$FUZZ_JOBS"

# The seeds: a run of the instrumented fpmshell makes the restart files, so that their layout is
# this build's.
PYTHON=$(test -x /usr/bin/python3 && echo /usr/bin/python3 || echo python3)
"$PYTHON" fuzz/seed_corpora.py --fpmshell "$FUZZ_BUILD/fpmshell" --out "$FUZZ_BUILD/seeds"

run_target() {
    local target=$1 build=$2 seconds=$3
    local corpus="$build/corpus/$target" findings="$build/findings/$target" log="$build/logs/$target.log"
    mkdir -p "$corpus" "$findings" "$build/logs"
    local status=0
    # -timeout: an input running longer is a hang; -rss_limit_mb: more memory is a finding (a
    # reader that allocates what a declared size asks before checking it); the regressions
    # are inputs too, so a fixed bug that comes back fails at once
    local inputs=("$corpus" "$build/seeds/$target")
    [[ -d "fuzz/regressions/$target" ]] && inputs+=("fuzz/regressions/$target")
    ASAN_OPTIONS=detect_leaks=1 "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=10 \
        -rss_limit_mb=2560 -dict="fuzz/dict/$target.dict" -artifact_prefix="$findings/" \
        -print_final_stats=1 "${inputs[@]}" >"$log" 2>&1 || status=$?
    local runs; runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
    local result=passed
    [[ $status -ne 0 ]] && result="FAILED (exit $status, see $log and $findings/)"
    printf '%-14s %10s executions in %4s s, corpus %5s inputs: %s\n' "$target" "${runs:-0}" \
        "$seconds" "$(ls "$corpus" | wc -l)" "$result"
    [[ $status -eq 0 ]]
}
export -f run_target

echo "fuzzing ${#TARGETS[@]} targets for $FUZZ_SECONDS s each, $FUZZ_JOBS at a time"
status=0
printf '%s\n' "${TARGETS[@]}" |
    xargs -P "$FUZZ_JOBS" -I{} bash -c 'run_target "$@"' _ {} "$FUZZ_BUILD" "$FUZZ_SECONDS" \
    | tee "$FUZZ_BUILD/fuzz_report.txt" || status=1
if [[ $status -ne 0 ]]; then
    echo "fuzz: a target failed; its input is in $FUZZ_BUILD/findings/<target>/" >&2
    exit 1
fi
echo "fuzz: every target passed ($FUZZ_BUILD/fuzz_report.txt)"

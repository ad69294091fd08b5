#!/usr/bin/env bash
# scripts/short_example_runs.sh FPMSHELL OUT: a short run of every example with the fpmshell at
# FPMSHELL (make sanitize, make tsan): set-up, the element and contact loops on 2 threads, output
# and a restart file, 40 stable steps long (check prints the stable step). Exits 1 at the first
# run that fails, with its error output.
set -euo pipefail
cd "$(dirname "$0")/.."
fpmshell=$1
out=$2
# Debian's interpreter, as the Makefile picks it (a python3 earlier on PATH may be another one)
python=$(test -x /usr/bin/python3 && echo /usr/bin/python3 || echo python3)
rm -rf "$out"
for model in examples/*/model.yaml; do
    name=$(basename "$(dirname "$model")")
    dt=$("$fpmshell" check "$model" | sed -n 's/.*stable time step *\([0-9.eE+-]*\).*/\1/p' | head -1)
    [[ -n "$dt" ]] || { echo "no stable step in the summary of $model" >&2; exit 1; }
    end=$("$python" -c "print(40 * $dt)")
    echo "$name: 40 steps (end_time $end) on 2 threads"
    "$fpmshell" run "$model" -o "$out/$name" --quiet --threads 2 \
        --restart-every 1e9 --set "control.end_time=$end" --set "output.every=0" >/dev/null 2>"$out.$name.err" ||
        { cat "$out.$name.err" >&2; echo "the run of $model failed" >&2; exit 1; }
done

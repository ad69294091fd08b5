#!/bin/bash
# Byte-for-byte comparison of two fpmshell builds: the quick variant of every validation problem
# and short runs of the three examples, with each binary; prints "DIFF <file>" for every
# history.csv, energy.csv and .vtu that differs and exits 1 if any does.
#   tools/compare_builds.sh OLD_BIN NEW_BIN [WORKDIR=build/compare]
# The old binary's outputs are kept in WORKDIR/old and reused while WORKDIR/old/done is newer
# than OLD_BIN (delete it to force a rerun).
# About 5 minutes per binary on the project's 2-core machine. The quick variants draw their
# plots into their own output folders, not into docs/validation/.
set -u
OLD=$(readlink -f "$1"); NEW=$(readlink -f "$2"); WORK=$(readlink -m "${3:-build/compare}")
SRC=$(cd "$(dirname "$0")/.." && pwd)
PY=$(test -x /usr/bin/python3 && echo /usr/bin/python3 || echo python3)
run_set() {  # binary output-folder
    local bin=$1 out=$2
    rm -rf "$out"; mkdir -p "$out"
    for v in "$SRC"/validation/*/; do
        n=$(basename "$v")
        [ -f "$v/run.py" ] || continue
        "$PY" "$v/run.py" --fpmshell "$bin" --out "$out/val/$n" --quick > "$out/val-$n.log" 2>&1 ||
            echo "run failed: $n ($bin)"
    done
    "$bin" run "$SRC/examples/spherical_cap_elastic/model.yaml" -o "$out/ex/cap" --overwrite --quiet \
        --set control.end_time=2e-4 > /dev/null 2>&1 || echo "cap failed ($bin)"
    "$bin" run "$SRC/examples/cylindrical_panel_impulse/model.yaml" -o "$out/ex/panel" --overwrite --quiet \
        --set control.end_time=1e-4 > /dev/null 2>&1 || echo "panel failed ($bin)"
    "$bin" run "$SRC/examples/square_tube/model.yaml" -o "$out/ex/tube" --overwrite --quiet \
        --set mesh.divisions_width=15 --set mesh.divisions_length=64 --set control.end_time=1e-3 \
        > /dev/null 2>&1 || echo "tube failed ($bin)"
}
if [ ! "$WORK/old/done" -nt "$OLD" ]; then
    run_set "$OLD" "$WORK/old" && touch "$WORK/old/done"
fi
run_set "$NEW" "$WORK/new"
status=0; n=0
while IFS= read -r f; do
    rel=${f#"$WORK/old/"}; n=$((n + 1))
    if ! cmp -s "$f" "$WORK/new/$rel"; then echo "DIFF $rel"; status=1; fi
done < <(find "$WORK/old" \( -name history.csv -o -name energy.csv -o -name '*.vtu' \) | sort)
echo "compared $n files, status $status"
exit $status

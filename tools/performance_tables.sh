#!/bin/sh
# Prints the figures of docs/performance.md, "Current figures": the commit and the machine, the
# whole-run table (bench/whole_run/run.py) and the figure-of-merit tables (fpmshell_bench
# --table), one and two threads. About 15 minutes on the project's 2-core machine; run it with
# nothing else running. The CalculiX comparison is separate (bench/calculix_compare.py, needs
# ccx, about 10 minutes; it writes bench/calculix_results.md).
#   tools/performance_tables.sh [BUILD_DIR]      (default build; needs targets fpmshell and
#                                                 fpmshell_bench)
set -e
BUILD=${1:-build}
cd "$(dirname "$0")/.."
state=$(git diff --quiet HEAD -- src app bench 2>/dev/null && echo "" || echo " + uncommitted changes")
echo "Commit: $(git rev-parse --short HEAD)$state, measured $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores"
echo
echo "## Whole run"
/usr/bin/python3 bench/whole_run/run.py --fpmshell "$BUILD/fpmshell" --out "$BUILD/whole_run" \
    --sizes 71,224,707 --steps 200 --threads 2
echo
echo "## Figure-of-merit table"
"$BUILD/bench/fpmshell_bench" --table --threads 2

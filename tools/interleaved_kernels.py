#!/usr/bin/python3
"""Crash kernel table of two builds, the two programs alternating (the machine's speed drifts:
only runs of one spell compare).
usage: tools/interleaved_kernels.py OLD_PROGRAM NEW_PROGRAM [rounds=3] [models=...]
       each program: bench/crash_kernels/crash_kernels.cpp built against one library
       (build/bench/fpmshell_crash_kernels; for an older library see docs/performance.md)
Prints ns per element-step (thread CPU time, one thread) of every run and, per model, the
ranges and the ratios new/old of the best and the median runs."""
import os, subprocess, sys
old, new = sys.argv[1], sys.argv[2]
rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 3
models = sys.argv[4] if len(sys.argv) > 4 else "jc,jc-rate,jc-n0.1,bilinear,elastic"
env = dict(os.environ, OMP_NUM_THREADS="1")
res = {}
for r in range(rounds):
    for tag, prog in (("old", old), ("new", new)):
        out = subprocess.run([prog, "--models", models], capture_output=True, text=True, env=env,
                             check=True).stdout
        for line in out.splitlines():
            cells = [c.strip() for c in line.strip("|").split("|")]
            if len(cells) == 5 and cells[2].replace(".", "").isdigit():
                res.setdefault((cells[0], tag), []).append(float(cells[2]))
                print("%s %s round %d: %s ns per element-step" % (cells[0], tag, r, cells[2]),
                      flush=True)
print("| model | old | new | ratio new/old, best | ratio, median |")
print("|---|---:|---:|---:|---:|")
for m in models.split(","):
    o, n = sorted(res[(m, "old")]), sorted(res[(m, "new")])
    print("| %s | %.0f–%.0f | %.0f–%.0f | %.2f | %.2f |" % (m, o[0], o[-1], n[0], n[-1], n[0] / o[0],
                                                         n[len(n) // 2] / o[len(o) // 2]))

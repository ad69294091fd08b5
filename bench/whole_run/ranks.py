#!/usr/bin/env python3
"""Distributed runs against one process (docs/performance.md, "Distributed runs").

Runs a model with `fpmshell run --threads T` on 1 process and under `mpirun -np N` (T threads
per rank), the two alternating for a few rounds (the machine's speed drifts), and prints the
time loop (summary.json wall_seconds) of each run, the ratio of the medians and whether
history.csv and energy.csv are the same bytes.

usage: bench/whole_run/ranks.py [--fpmshell build/fpmshell] [--model plate_elastic.yaml]
                                [--ranks 2] [--threads 1] [--rounds 3] [--set KEY=VALUE ...]
Default: the elastic 10^5 plate to 4e-4 s (764 steps, 11 history rows, 2 frames).
"""
import argparse
import filecmp
import json
import os
import shutil
import statistics
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

ap = argparse.ArgumentParser()
ap.add_argument("--fpmshell", default=os.path.join(ROOT, "build", "fpmshell"))
ap.add_argument("--model", default=os.path.join(HERE, "plate_elastic.yaml"))
ap.add_argument("--ranks", type=int, default=2)
ap.add_argument("--threads", type=int, default=1)
ap.add_argument("--rounds", type=int, default=3)
ap.add_argument("--set", action="append", default=None)
a = ap.parse_args()
sets = a.set or ["control.end_time=4e-4", "output.every=4e-5"]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="fpmshell-ranks-")
walls = {1: [], a.ranks: []}
same = True
for r in range(a.rounds):
    for ranks in (1, a.ranks):
        out = os.path.join(work, "np%d" % ranks)
        shutil.rmtree(out, ignore_errors=True)
        cmd = [a.fpmshell, "run", a.model, "-o", out, "--threads", str(a.threads), "--quiet"]
        for s in sets:
            cmd += ["--set", s]
        if ranks > 1:
            cmd = ["mpirun", "-np", str(ranks), "--bind-to", "core"] + cmd
        subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        walls[ranks].append(summary["wall_seconds"])
        print("round %d, %d rank(s): %d steps, time loop %.3f s" % (
            r, ranks, summary["steps"], summary["wall_seconds"]), flush=True)
    for name in ("history.csv", "energy.csv"):
        same = same and filecmp.cmp(os.path.join(work, "np1", name),
                                    os.path.join(work, "np%d" % a.ranks, name), shallow=False)
one, many = statistics.median(walls[1]), statistics.median(walls[a.ranks])
print("| ranks x threads | time loop, s (median of %d) | speed-up | same bytes |" % a.rounds)
print("|---|---:|---:|---|")
print("| 1 x %d | %.3f | 1 | |" % (a.threads, one))
print("| %d x %d | %.3f | %.2f | %s |" % (a.ranks, a.threads, many, one / many,
                                          "yes" if same else "**no**"))
shutil.rmtree(work)

#!/usr/bin/python3
"""Time-loop speed of two fpmshell builds on the plates of bench/whole_run, the two binaries
alternating (the machine's speed drifts: only runs of one spell compare).
usage: tools/interleaved_speed.py OLD_BIN NEW_BIN [rounds=3] [nx=224] [steps=150]
       (THREADS=2 in the environment for two threads; nx=224 is 10^5 triangles)
Prints ns per element-step (summary.json) of every run and the ratios new/old of the best and
the median runs."""
import json, os, re, subprocess, sys
old, new = sys.argv[1], sys.argv[2]
rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 3
nx = int(sys.argv[4]) if len(sys.argv) > 4 else 224
steps = int(sys.argv[5]) if len(sys.argv) > 5 else 150
B = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench", "whole_run")
res = {}
for model in ("plate_elastic", "plate_plastic"):
    y = os.path.join(B, model + ".yaml")
    out = subprocess.run([old, "check", y, "--set", "mesh.nx=%d" % nx, "--set", "mesh.ny=%d" % nx], capture_output=True, text=True).stdout
    dt = float(re.search(r"stable time step ([0-9.eE+-]+)", out).group(1))
    for r in range(rounds):
        for tag, b in (("old", old), ("new", new)):
            d = "/tmp/speed_%s_%s" % (model, tag)
            subprocess.run([b, "run", y, "-o", d, "--quiet", "--overwrite", "--threads", os.environ.get("THREADS", "1"), "--set", "mesh.nx=%d" % nx,
                            "--set", "mesh.ny=%d" % nx, "--set", "control.end_time=%.9g" % (steps * dt)], check=True, capture_output=True)
            s = json.load(open(os.path.join(d, "summary.json")))
            ns = 1e9 / s["element_steps_per_second"]
            res.setdefault((model, tag), []).append(ns)
            print("%s %s round %d: %.1f ns per element-step" % (model, tag, r, ns), flush=True)
for model in ("plate_elastic", "plate_plastic"):
    o, n = res[(model, "old")], res[(model, "new")]
    print("%s: old %s  new %s  best new/old %.3f  median new/old %.3f" % (model, ["%.1f" % v for v in o], ["%.1f" % v for v in n],
          min(n) / min(o), sorted(n)[len(n)//2] / sorted(o)[len(o)//2]))

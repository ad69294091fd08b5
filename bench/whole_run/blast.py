#!/usr/bin/env python3
"""The cost of an air blast (theory.md §6.13) in a step (docs/performance.md, "Blast loads").

Runs the clamped 10^5-triangle plate of plate_elastic.yaml with its uniform pressure, and the
same plate with a blast in place of the pressure (1 kg of TNT in free air 0.5 m over its centre,
detonated early enough that every face is inside its positive phase during the run: the
pulses' exponentials are evaluated on every face at every step), the two alternating for a few
rounds (the machine's speed drifts), and prints the time loop (summary.json wall_seconds) of
each, their medians and the ratios: the blast's share of a step, at its worst (every face in
its phase) and before the shock arrives (a charge detonated later than the run ends).

usage: bench/whole_run/blast.py [--fpmshell build/fpmshell] [--rounds 5] [--threads 1]
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

ap = argparse.ArgumentParser()
ap.add_argument("--fpmshell", default=os.path.join(ROOT, "build", "fpmshell"))
ap.add_argument("--rounds", type=int, default=5)
ap.add_argument("--threads", type=int, default=1)
a = ap.parse_args()

work = tempfile.mkdtemp(prefix="fpmshell-blast-")
with open(os.path.join(HERE, "plate_elastic.yaml")) as f:
    plate = f.read()
pressure = "  - {type: pressure, elements: all, value: 1.0e3}\n"
assert pressure in plate
# the faces' arrivals span 0.16 to 0.55 ms and their phases last 0.43 to 0.62 ms: detonated
# 0.6 ms before t = 0, every face is in its positive phase over the 0.1 ms run
blast = ("  - {type: blast, elements: all, charge_mass: 1.0, centre: [0.5, 0.5, 0.5],\n"
         "     detonation_time: -6.0e-4}\n")
models = {}
quiet = blast.replace("detonation_time: -6.0e-4", "detonation_time: 1.0")  # not yet arrived
for name, load in (("pressure", pressure), ("blast", blast), ("blast not arrived", quiet)):
    models[name] = os.path.join(work, name.replace(" ", "_") + ".yaml")
    with open(models[name], "w") as f:
        f.write(plate.replace(pressure, load))
walls = {name: [] for name in models}
steps = {}
for r in range(a.rounds):
    for name, model in models.items():
        out = os.path.join(work, name.replace(" ", "_"))
        subprocess.run([a.fpmshell, "run", model, "-o", out, "--overwrite", "--quiet",
                        "--threads", str(a.threads)], check=True)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        walls[name].append(s["wall_seconds"])
        steps[name] = s["steps"]
        print("round %d %s: %.3f s, %d steps" % (r, name, s["wall_seconds"], s["steps"]), flush=True)
median = {name: statistics.median(w) for name, w in walls.items()}
print("| load | time loop, median of %d (s) | steps | per step (ms) | against the pressure |"
      % a.rounds)
print("|---|---:|---:|---:|---:|")
base = median["pressure"] / steps["pressure"]
for name in models:
    per_step = median[name] / steps[name]
    print("| %s | %.3f | %d | %.3f | %.3f |" % (name, median[name], steps[name], 1e3 * per_step,
                                               per_step / base))

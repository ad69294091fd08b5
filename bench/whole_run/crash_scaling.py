#!/usr/bin/env python3
"""A 10^6-triangle model in contact over ranks (docs/performance.md, "Distributed runs": a large model in contact over
ranks").

pressed_layers.yaml: two layers of 500 x 500 quadrilaterals (10^6 triangles) pressed together,
the self-contact active at every particle of the top layer from the second step (the mesh file
is written here, beside a copy of the model): `fpmshell run` on 1, 2 and 4 ranks (one thread each; 4 ranks on a 2-core machine share the cores: their traffic, not their
speed, is what they show), each to two end times. Per rank count it prints:
- the marginal cost of a step, (time loop at t2 - time loop at t1) / (steps at t2 - steps at
  t1): the set-up, the first contact search and the frames at the start and the end cancel;
- the contact's share of those steps, from the contact seconds the log reports at both times;
- the peak resident memory of each rank (/usr/bin/time around each rank);
then a scaling model calibrated on these (the docs explain it) and its projection to 8-1024
ranks, with the contact computed whole on every rank (as it is) and shared over the ranks.

usage: bench/whole_run/crash_scaling.py [--fpmshell build/fpmshell] [--ranks 1,2,4]
                                        [--times 3e-6,6e-6]
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from layers_mesh import write_layers_mesh  # noqa: E402
ROOT = os.path.dirname(os.path.dirname(HERE))
CELLS, WIDTH, GAP = 500, 0.5, 1.0001e-3  # per layer and side; the layers' mid-surfaces apart


ap = argparse.ArgumentParser()
ap.add_argument("--fpmshell", default=os.path.join(ROOT, "build", "fpmshell"))
ap.add_argument("--ranks", default="1,2,4")
ap.add_argument("--times", default="3e-6,6e-6")
a = ap.parse_args()
ranks_list = [int(r) for r in a.ranks.split(",")]
t1, t2 = (float(t) for t in a.times.split(","))
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
work = tempfile.mkdtemp(prefix="fpmshell-crash-scaling-")
model = os.path.join(work, "pressed_layers.yaml")
shutil.copy(os.path.join(HERE, "pressed_layers.yaml"), model)
write_layers_mesh(os.path.join(work, "pressed_layers_mesh.k"), CELLS, WIDTH, GAP)


def run(ranks, end):
    out = os.path.join(work, "np%d_%g" % (ranks, end))
    cmd = ["/usr/bin/time", "-f", "peak_kb %M", a.fpmshell, "run", model, "-o", out, "--threads",
           "1", "--quiet", "--overwrite", "--set", "control.end_time=%g" % end]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--oversubscribe", "--bind-to", "none"] + cmd
    r = subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                       check=True)
    peaks = [int(k) / 1024 ** 2 for k in re.findall(r"peak_kb (\d+)", r.stderr)]
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    with open(os.path.join(out, "log.txt")) as f:
        contact = float(re.findall(r"searches, ([0-9.]+) s \(", f.read())[-1])
    return s["steps"], s["wall_seconds"], contact, peaks


rows = {}
for ranks in ranks_list:
    s1, w1, c1, p1 = run(ranks, t1)
    s2, w2, c2, p2 = run(ranks, t2)
    step = (w2 - w1) / (s2 - s1)
    contact = (c2 - c1) / (s2 - s1)
    rows[ranks] = (step, contact, max(p1 + p2), min(p1 + p2))
    print("%d rank(s): %d and %d steps, time loops %.2f and %.2f s; contact %.2f and %.2f s; "
          "peak memory per rank %s GB" % (ranks, s1, s2, w1, w2, c1, c2,
                                          ", ".join("%.2f" % p for p in p2)), flush=True)

print()
print("| ranks x threads | s per step (marginal) | contact s per step | contact share | "
      "speed-up | largest rank's peak memory, GB |")
print("|---|---:|---:|---:|---:|---:|")
base = rows[ranks_list[0]][0]
for ranks, (step, contact, peak, _) in rows.items():
    print("| %d x 1 | %.4f | %.4f | %.0f %% | %.2f | %.2f |" % (
        ranks, step, contact, 100 * contact / step, base / step, peak))

# The scaling model: a step on N ranks costs E / N (the element loop and the particles, cut
# over the ranks) + C (the contact, whole on every rank today) + H(N) (the halo's traffic and
# the ranks' imbalance), H(1) = 0. On 1 rank: E = T1 - C1. On 2 ranks H(2) = T2 - E / 2 - C2.
# The halo of a part of a surface mesh grows as its perimeter: H(N) = H(2) sqrt(2 / N) per
# rank's part, plus nothing for latency on this shared-memory machine (a cluster adds its own).
if 1 in rows and 2 in rows:
    T1, C1 = rows[1][0], rows[1][1]
    T2, C2 = rows[2][0], rows[2][1]
    E = T1 - C1
    H2 = T2 - E / 2 - C2
    print()
    print("model: E = %.4f s (elements and particles), C = %.4f s (contact), H(2) = %.4f s "
          "(halo and imbalance at 2 ranks)" % (E, C1, H2))
    print("| ranks | contact whole on every rank, ms per step | contact shared, ms per step |")
    print("|---:|---:|---:|")
    for n in (8, 16, 64, 256, 1024):
        h = max(H2, 0.0) * (2.0 / n) ** 0.5
        print("| %d | %.2f | %.2f |" % (n, 1e3 * (E / n + C1 + h), 1e3 * ((E + C1) / n + h)))

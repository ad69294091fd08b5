#!/usr/bin/python3
"""Halo traffic of a distributed run against the part count (docs/performance.md, "Distributed
runs: the halo per step"), from `fpmshell partition` on the elastic plate of bench/whole_run at
10^6 and 10^7 triangles.

usage: tools/scaling_model.py [FPMSHELL] [--sizes 708,2236] [--parts 2,8,64,512]
                              [--ns 119] [--bandwidth 10] [--latency 2]
For each size and part count: the largest part's elements, shared particles, received corner
loads (48 bytes each) and neighbours, and a model of one step on that part: compute = elements
x ns per element-step (one core: the whole-run figure of docs/performance.md), exchange =
bytes / bandwidth (GB/s) + neighbours x latency (us), with the exchange overlapped by the
interior elements (the step takes the larger of the two plus the boundary elements' share) or
not (their sum). Contact is not in the model (it is computed on every rank)."""
import argparse
import os
import re
import subprocess

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
PLATE = os.path.join(ROOT, "bench", "whole_run", "plate_elastic.yaml")

ap = argparse.ArgumentParser()
ap.add_argument("fpmshell", nargs="?", default=os.path.join(ROOT, "build", "fpmshell"))
ap.add_argument("--sizes", default="708,2236")
ap.add_argument("--parts", default="2,8,64,512")
ap.add_argument("--ns", type=float, default=119.0)
ap.add_argument("--bandwidth", type=float, default=10.0)
ap.add_argument("--latency", type=float, default=2.0)
a = ap.parse_args()

print("| triangles | parts | elements (largest part) | shared particles | received kB | "
      "neighbours | compute µs | exchange µs | efficiency, overlapped | not overlapped |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for n in a.sizes.split(","):
    for p in a.parts.split(","):
        out = subprocess.run([a.fpmshell, "partition", PLATE, "--set", "mesh.nx=" + n, "--set",
                              "mesh.ny=" + n, "--parts", p], capture_output=True, text=True,
                             check=True).stdout
        rows = [r for r in out.splitlines() if re.match(r"^\| \d+ \|", r)]
        cells = [[float(c) for c in r.strip("|").split("|")] for r in rows]
        total = int(re.search(r"^(\d+) elements", out).group(1))
        # the slowest part: the most elements (its compute) and its own halo
        worst = max(cells, key=lambda c: (c[2], c[7]))
        elements, shared, slots, neighbours = worst[2], worst[6], worst[7], worst[9]
        compute = elements * a.ns * 1e-3  # us
        exchange = slots * 48 / (a.bandwidth * 1e3) + neighbours * a.latency  # us
        ideal = total * a.ns * 1e-3 / int(p)
        boundary = shared / max(elements, 1) * compute  # the elements the halo waits on, roughly
        overlapped = max(compute, exchange + boundary)
        print("| %d | %s | %d | %d | %.1f | %d | %.0f | %.1f | %.2f | %.2f |" % (
            total, p, elements, shared, slots * 48 / 1e3, neighbours, compute, exchange,
            ideal / overlapped, ideal / (compute + exchange)))

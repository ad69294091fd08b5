#!/usr/bin/env python3
"""Whole-run cost of `fpmshell run` per element-step (docs/performance.md, "Whole run").

Runs the clamped plate under a sudden pressure (plate_elastic.yaml: 2 Gauss x 3 points;
plate_plastic.yaml: 5 Lobatto x 3 points, every point yielding) on about 10^4, 10^5 and 10^6
triangles, with 1 thread and with all threads, and prints one markdown table:
- whole run: wall time of the process (reading the model, building the mesh and the solver,
  the time loop, writing every result file) / (elements x steps);
- time loop: the same from summary.json (the loop alone);
- the speed-up of all threads over one, and whether history.csv is byte for byte the same.

usage: bench/whole_run/run.py [--fpmshell build/fpmshell] [--out DIR] [--sizes 71,224,708]
                              [--steps 200] [--threads N]
The largest mesh (708: 1 002 528 triangles) takes about 3 minutes per run on one thread.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def stable_dt(fpm, model, nx):
    out = subprocess.run([fpm, "check", model, "--set", "mesh.nx=%d" % nx, "--set", "mesh.ny=%d" % nx],
                         capture_output=True, text=True, check=True).stdout
    return float(re.search(r"stable time step ([0-9.eE+-]+)", out).group(1))


def run(fpm, model, out, nx, end, threads):
    cmd = [fpm, "run", model, "-o", out, "--quiet", "--overwrite", "--threads", str(threads),
           "--set", "mesh.nx=%d" % nx, "--set", "mesh.ny=%d" % nx, "--set", "control.end_time=%.9g" % end]
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), p.stdout[-2000:] + p.stderr[-2000:]))
    s = json.load(open(os.path.join(out, "summary.json")))
    history = open(os.path.join(out, "history.csv")).read()
    return s, wall, history


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fpmshell", default="build/fpmshell")
    ap.add_argument("--out", default="build/whole_run")
    ap.add_argument("--sizes", default="71,224,708", help="mesh.nx values (2 nx^2 triangles)")
    ap.add_argument("--steps", type=int, default=200, help="about this many steps per run")
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1, help="'all threads' (default: cores)")
    ap.add_argument("--models", default="plate_elastic,plate_plastic")
    args = ap.parse_args()
    rows = []
    for name in args.models.split(","):
        model = os.path.join(HERE, name + ".yaml")
        for nx in [int(n) for n in args.sizes.split(",")]:
            end = args.steps * stable_dt(args.fpmshell, model, nx)
            results = {}
            for threads in sorted({1, args.threads}):
                out = os.path.join(args.out, "%s_%d_t%d" % (name, nx, threads))
                results[threads] = run(args.fpmshell, model, out, nx, end, threads)
            one = results[1]
            for threads, (s, wall, history) in sorted(results.items()):
                el_steps = s["elements"] * s["steps"]
                rows.append((name, s["elements"], threads, s["steps"], 1e9 * wall / el_steps,
                             1e9 / s["element_steps_per_second"],
                             one[0]["element_steps_per_second"] and
                             s["element_steps_per_second"] / one[0]["element_steps_per_second"],
                             "yes" if history == one[2] else "NO",
                             s["plastic_strain"]["max"]))
                r = rows[-1]
                print("%-14s %9d el %2d thr: whole run %7.1f ns, loop %7.1f ns per element-step"
                      % (r[0], r[1], r[2], r[4], r[5]), flush=True)
    cpu = ""
    try:
        cpu = re.search(r"Model name:\s*(.+)", subprocess.run(["lscpu"], capture_output=True, text=True).stdout).group(1)
    except (OSError, AttributeError):
        pass
    print("\nMachine: %s, %d cores. Command: %s\n" % (cpu.strip(), os.cpu_count() or 1, " ".join(sys.argv)))
    print("| model | elements | threads | steps | whole run ns / element-step | time loop ns / element-step "
          "| loop speed-up | history.csv as 1 thread | peak plastic strain |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %d | %d | %d | %.0f | %.0f | %.2f | %s | %.3g |" % r)


if __name__ == "__main__":
    main()

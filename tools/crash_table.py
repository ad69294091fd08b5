#!/usr/bin/python3
"""Crash benchmark, contact rows (docs/performance.md, "Crash models"): whole runs of two fpmshell
builds, alternating (the machine's speed drifts: only runs of one spell compare).

usage: tools/crash_table.py OLD_BIN NEW_BIN [--rounds 1] [--threads 1,2] [--cases quick,crush,paper]
  quick  examples/square_tube on 15 x 64 (3 840 triangles), its first 5 ms
  crush  bench/whole_run/crush_half_cylinder.yaml (900 triangles, Johnson-Cook, self-contact
         and two rigid walls), to its end time
  paper  examples/square_tube on the paper's 30 x 128 (15 360 triangles), its first 5 ms
For every case and thread count it prints, per build, the time loop's ns per element-step
(summary.json), the steps, the wall time of the process and the contact's share of the time
loop, then the ratios new/old (best of the rounds) and 2 threads over 1 of each build, and
whether history.csv is the same bytes on every thread count of a build."""
import argparse
import json
import os
import subprocess
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
TUBE = os.path.join(ROOT, "examples", "square_tube", "model.yaml")
CASES = {
    "quick": (TUBE, ["mesh.divisions_width=15", "mesh.divisions_length=64", "control.end_time=5e-3"]),
    "crush": (os.path.join(ROOT, "bench", "whole_run", "crush_half_cylinder.yaml"), []),
    "paper": (TUBE, ["mesh.divisions_width=30", "mesh.divisions_length=128", "control.end_time=5e-3"]),
}


def run(binary, model, sets, threads, out):
    cmd = [binary, "run", model, "-o", out, "--quiet", "--overwrite", "--threads", str(threads)]
    for s in sets:
        cmd += ["--set", s]
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, capture_output=True)
    wall = time.perf_counter() - t0
    s = json.load(open(os.path.join(out, "summary.json")))
    with open(os.path.join(out, "history.csv"), "rb") as f:
        history = f.read()
    return {"ns": 1e9 / s["element_steps_per_second"], "steps": s["steps"], "wall": wall,
            "contact": s.get("contact", {}).get("share_of_time_loop", 0.0), "history": history}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--cases", default="quick,crush,paper")
    ap.add_argument("--out", default="/tmp/crash_table")
    args = ap.parse_args()
    threads = [int(t) for t in args.threads.split(",")]
    res = {}
    for case in args.cases.split(","):
        model, sets = CASES[case]
        for r in range(args.rounds):
            for t in threads:
                for tag, binary in (("old", args.old), ("new", args.new)):
                    x = run(binary, model, sets, t, os.path.join(args.out, "%s_%s_%d" % (case, tag, t)))
                    res.setdefault((case, tag, t), []).append(x)
                    print("%s %s %d thread(s) round %d: %.0f ns per element-step, %d steps, %.1f s wall, "
                          "contact %.1f %% of the loop" % (case, tag, t, r, x["ns"], x["steps"], x["wall"],
                                                          100 * x["contact"]), flush=True)
    print()
    print("| case | threads | old ns/elem-step | new ns/elem-step | new/old | steps old / new | wall old / new [s] "
          "| contact share old / new |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for case in args.cases.split(","):
        for t in threads:
            o = min(res[(case, "old", t)], key=lambda x: x["ns"])
            n = min(res[(case, "new", t)], key=lambda x: x["ns"])
            print("| %s | %d | %.0f | %.0f | %.3f | %d / %d | %.1f / %.1f | %.1f %% / %.1f %% |"
                  % (case, t, o["ns"], n["ns"], n["ns"] / o["ns"], o["steps"], n["steps"], o["wall"], n["wall"],
                     100 * o["contact"], 100 * n["contact"]))
    if len(threads) > 1:
        print()
        for case in args.cases.split(","):
            for tag in ("old", "new"):
                base = min(x["ns"] for x in res[(case, tag, threads[0])])
                same = all(x["history"] == res[(case, tag, threads[0])][0]["history"]
                           for t in threads for x in res[(case, tag, t)])
                print("%s %s: %s; history.csv %s on every thread count" % (
                    case, tag, ", ".join("%d threads %.2fx" % (t, base / min(x["ns"] for x in res[(case, tag, t)]))
                                         for t in threads[1:]), "the same bytes" if same else "DIFFERENT"))


if __name__ == "__main__":
    main()

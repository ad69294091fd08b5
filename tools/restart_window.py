#!/usr/bin/python3
"""Cost of a window of a run, continued from a restart file, with two builds alternating
(docs/performance.md, "The paper's tube to the block's stop"; the machine's speed drifts: only runs of one
spell compare).

usage: tools/restart_window.py OLD_FPMSHELL NEW_FPMSHELL MODEL RESTART_DIR END_TIME
                               [--rounds 3] [--threads 1,2] [--set key=value ...]
RESTART_DIR holds restart.bin and the results of a run of MODEL (fpmshell run MODEL -o DIR
--restart-every 1e9 --set control.end_time=T0). Each build continues a copy of it to END_TIME
(--resume); the window's figures are the differences of summary.json before and after:
ns per element-step of the time loop and the contact's share of it. Prints every run, the
ranges per build and thread count, and whether both builds wrote the same history.csv."""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import tempfile


def loop_seconds(summary):
    contact = summary["contact"]
    return contact["seconds"] / contact["share_of_time_loop"]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("model")
    ap.add_argument("restart_dir")
    ap.add_argument("end_time", type=float)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--set", action="append", default=[])
    args = ap.parse_args()
    base = json.load(open(os.path.join(args.restart_dir, "summary.json")))
    work = tempfile.mkdtemp(prefix="restart_window_")
    results, histories = {}, {}
    for r in range(args.rounds):
        for threads in [int(t) for t in args.threads.split(",")]:
            for tag, program in (("old", args.old), ("new", args.new)):
                out = os.path.join(work, "%s_%d" % (tag, threads))
                shutil.rmtree(out, ignore_errors=True)
                shutil.copytree(args.restart_dir, out)
                cmd = [program, "run", args.model, "-o", out, "--resume", "--overwrite", "--quiet",
                       "--threads", str(threads), "--set", "control.end_time=%.9g" % args.end_time]
                for s in args.set:
                    cmd += ["--set", s]
                subprocess.run(cmd, check=True, capture_output=True)
                s = json.load(open(os.path.join(out, "summary.json")))
                steps = s["steps"] - base["steps"]
                loop = loop_seconds(s) - loop_seconds(base)
                contact = s["contact"]["seconds"] - base["contact"]["seconds"]
                ns = 1e9 * loop / (s["elements"] * steps)
                results.setdefault((tag, threads), []).append((ns, contact / loop))
                histories[(tag, threads)] = open(os.path.join(out, "history.csv")).read()
                print("round %d %s, %d thread(s): %d steps, %.1f ns per element-step, contact %.1f %%"
                      % (r, tag, threads, steps, ns, 100 * contact / loop), flush=True)
    for (tag, threads), runs in sorted(results.items()):
        print("%s, %d thread(s): %.0f-%.0f ns per element-step (median %.0f), contact %.1f-%.1f %% "
              "(median %.1f %%)"
              % (tag, threads, min(x[0] for x in runs), max(x[0] for x in runs),
                 statistics.median(x[0] for x in runs), 100 * min(x[1] for x in runs),
                 100 * max(x[1] for x in runs), 100 * statistics.median(x[1] for x in runs)))
    for threads in sorted({t for _, t in histories}):
        same = histories[("old", threads)] == histories[("new", threads)]
        print("%d thread(s): history.csv the same bytes for both builds: %s" % (threads, same))
    shutil.rmtree(work)


if __name__ == "__main__":
    main()

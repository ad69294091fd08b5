#!/usr/bin/python3
"""Validation problems under model options: runs validation/<problem>/run.py (quick variants, or
full ones with --full) once per configuration, the keys of each written into every model by
tools/with_keys.py, and prints, as markdown, every tested row's value and pass/fail per
configuration and, per problem, the stable step at the start and the mean step against the
first configuration.
usage: tools/option_study.py --fpmshell BIN --out DIR --config NAME=KEYS [--config ...]
                             [--problems p1,p2] [--full] [--table-only]
  KEYS as FPM_KEYS of tools/with_keys.py; an empty KEYS is the model as it is, e.g.
  --config default= --config abaqus='control.rotary_inertia=abaqus'
Runs go to DIR/<config>/<problem>; --table-only prints the table of runs already made."""
import argparse
import glob
import json
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
PY = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable


def rows(out, config, problem):
    try:
        with open(os.path.join(out, config, problem, "rows.json")) as f:
            return json.load(f)
    except OSError:
        return []


def steps(out, config, problem):
    """Per run folder: (stable step at the start, end time / steps: the mean step of a dynamic
    run, the load increment per iteration of a relaxation run)."""
    found = {}
    for s in glob.glob(os.path.join(out, config, problem, "**", "summary.json"), recursive=True):
        run = os.path.dirname(s)
        with open(s) as f:
            summary = json.load(f)
        first = None
        try:
            with open(os.path.join(run, "log.txt")) as f:
                m = re.search(r"stable time step ([0-9.eE+-]+)", f.read())
            first = float(m.group(1)) if m else None
        except OSError:
            pass
        mean = summary["end_time"] / summary["steps"] if summary.get("steps") else None
        found[os.path.relpath(run, os.path.join(out, config, problem))] = (first, mean)
    return found


def value_text(r):
    v = r.get("value")
    text = "%.6g" % v if isinstance(v, (int, float)) else str(v)
    if r.get("tolerance") is not None:
        text += " " + ("pass" if r.get("pass") else "**FAIL**")
    return text


def table(out, configs, problems):
    names = [n for n, _ in configs]
    print("| problem | quantity | mesh | reference | tolerance | " + " | ".join(names) + " |")
    print("|---|---|---|---|---|" + "---|" * len(names))
    for p in problems:
        per = {n: {(r["quantity"], r.get("mesh", "")): r for r in rows(out, n, p)} for n in names}
        for r in rows(out, names[0], p):
            if r.get("tolerance") is None:
                continue
            key = (r["quantity"], r.get("mesh", ""))
            cells = [value_text(per[n][key]) if key in per[n] else "–" for n in names]
            ref = r.get("reference_text") or ("%.5g" % r["reference"] if isinstance(
                r.get("reference"), (int, float)) else str(r.get("reference")))
            print("| %s | %s | %s | %s | %.3g | %s |" % (p, r["quantity"], r.get("mesh", ""), ref,
                  r["tolerance"], " | ".join(cells)))
    print()
    print("| problem | configuration | runs | stable step at the start / %s | end time per step / %s |"
          % (names[0], names[0]))
    print("|---|---|---|---|---|")
    for p in problems:
        base = steps(out, names[0], p)
        for n in names[1:]:
            other = steps(out, n, p)
            first = [other[k][0] / v[0] for k, v in base.items() if k in other and v[0] and other[k][0]]
            mean = [other[k][1] / v[1] for k, v in base.items() if k in other and v[1] and other[k][1]]
            span = lambda x: "x%.3f ... x%.3f" % (min(x), max(x)) if x else "–"
            print("| %s | %s | %d | %s | %s |" % (p, n, len(first), span(first),
                  span(mean)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--fpmshell", default=os.path.join(ROOT, "build", "fpmshell"))
    ap.add_argument("--out", required=True)
    ap.add_argument("--config", action="append", required=True, help="NAME=KEYS")
    ap.add_argument("--problems", help="comma-separated (default: every validation problem)")
    ap.add_argument("--full", action="store_true", help="full variants (default: quick)")
    ap.add_argument("--table-only", action="store_true")
    args = ap.parse_args()
    configs = [tuple(c.split("=", 1)) if "=" in c else (c, "") for c in args.config]
    problems = args.problems.split(",") if args.problems else sorted(
        os.path.basename(os.path.dirname(r)) for r in glob.glob(os.path.join(ROOT, "validation", "*", "run.py")))
    out = os.path.abspath(args.out)
    if not args.table_only:
        env = dict(os.environ, FPM_BIN=os.path.abspath(args.fpmshell))
        for name, keys in configs:
            env["FPM_KEYS"] = keys
            for p in problems:
                target = os.path.join(out, name, p)
                os.makedirs(target, exist_ok=True)
                cmd = [PY, os.path.join(ROOT, "validation", p, "run.py"), "--fpmshell",
                       os.path.join(ROOT, "tools", "with_keys.py"), "--out", target]
                if not args.full:
                    cmd.append("--quick")
                with open(target + ".log", "w") as log:
                    rc = subprocess.call(cmd, env=env, stdout=log, stderr=subprocess.STDOUT)
                print("%s %s: exit %d" % (name, p, rc), file=sys.stderr, flush=True)
    table(out, configs, problems)


if __name__ == "__main__":
    main()

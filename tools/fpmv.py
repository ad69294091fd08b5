"""Shared helpers of the verification/validation problem scripts (validation/<name>/run.py).

Protocol of a problem script (see validation/README.md):
    run.py --fpmshell PATH --out DIR [--quick]
runs fpmshell on its model(s), compares with the reference, writes DIR/rows.json (one row per
compared quantity, fields below), draws its plots into docs/validation/, prints one line per row
and a closing 'N passed, M failed' line, and exits 0 only when every row passed.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PLOT_DIR = os.path.join(ROOT, "docs", "validation")


def parse_args(description, extra=None):
    """The common options; extra(parser) adds a problem's own."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--fpmshell", default=os.path.join(ROOT, "build", "fpmshell"))
    ap.add_argument("--out", required=True, help="folder for the runs and rows.json")
    ap.add_argument("--quick", action="store_true", help="coarse meshes only (make test)")
    ap.add_argument("--reuse", action="store_true",
                    help="use a run already in --out when it completed to the same end time with "
                         "the same particle and element counts (for problems that take hours)")
    if extra:
        extra(ap)
    return ap.parse_args()


def run(fpmshell, model, out_dir, overrides=(), threads=None):
    """Runs fpmshell on model into out_dir with --set overrides; returns (results dict, wall s).
    Raises RuntimeError with the log tail when fpmshell fails."""
    cmd = [fpmshell, "run", model, "-o", out_dir, "--quiet", "--overwrite"]
    for o in overrides:
        cmd += ["--set", o]
    if threads:
        cmd += ["--threads", str(threads)]
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        raise RuntimeError("fpmshell failed (exit %d): %s\n%s" % (p.returncode, " ".join(cmd),
                                                                  (p.stdout + p.stderr)[-3000:]))
    return read_results(out_dir), wall


def reusable(out_dir, end_time, particles=None, elements=None):
    """(results, wall) of a completed earlier run in out_dir that reached end_time (and has
    these counts, when given), else None."""
    try:
        res = read_results(out_dir)
    except (OSError, ValueError, IndexError):
        return None
    s = res["summary"]
    reason = s.get("exit_reason", "")
    body_stopped = reason.startswith("completed: rigid body")  # control.end_when_body_stops
    if not (reason == "completed" or body_stopped) or (
            not body_stopped and s.get("end_time", 0) < end_time * (1 - 1e-9)):
        return None
    if (particles is not None and s.get("particles") != particles) or (
            elements is not None and s.get("elements") != elements):
        return None
    return res, s.get("wall_seconds", 0.0)


def read_csv(path):
    """CSV with one header line -> dict column name -> list of floats."""
    with open(path) as f:
        rows = list(csv.reader(f))
    head, data = rows[0], rows[1:]
    return {h: [float(r[i]) for r in data] for i, h in enumerate(head)}


def read_results(out_dir):
    res = {"history": read_csv(os.path.join(out_dir, "history.csv")),
           "energy": read_csv(os.path.join(out_dir, "energy.csv"))}
    with open(os.path.join(out_dir, "summary.json")) as f:
        res["summary"] = json.load(f)
    return res


def row(problem, quantity, reference, value, tolerance, mesh="", wall=0.0, plot="", note="",
        relative=True, unit=""):
    """One compared quantity. relative: error = |value - reference| / |reference|, else absolute.
    tolerance is on the same scale as error; a None tolerance means 'reported, not tested'."""
    err = abs(value - reference) / abs(reference) if relative and reference != 0 else abs(value - reference)
    ok = True if tolerance is None else err <= tolerance
    return {"problem": problem, "quantity": quantity, "reference": reference, "value": value,
            "error": err, "relative": relative, "tolerance": tolerance, "unit": unit, "mesh": mesh,
            "wall_seconds": wall, "plot": plot, "note": note, "pass": ok}


def finish(out_dir, rows):
    """Writes rows.json, prints the rows and the closing line; returns the exit code."""
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "rows.json"), "w") as f:
        json.dump(rows, f, indent=1)
    n_fail = 0
    for r in rows:
        status = "ok  " if r["pass"] else "FAIL"
        if not r["pass"]:
            n_fail += 1
        tol = "report only" if r["tolerance"] is None else "tol %.3g" % r["tolerance"]
        print("%s %s | %s | mesh %s: ref %.6g, got %.6g, error %.3g (%s)" % (
            status, r["problem"], r["quantity"], r["mesh"], r["reference"], r["value"],
            r["error"], tol))
    print("%d passed, %d failed" % (len(rows) - n_fail, n_fail))
    return 0 if n_fail == 0 else 1


def observed_order(w1, w2, w3):
    """Convergence order from three meshes, each halving the element size:
    log2((w1 - w2) / (w2 - w3)); nan when the sequence is not monotone."""
    d1, d2 = w1 - w2, w2 - w3
    if d2 == 0 or d1 / d2 <= 0:
        return float("nan")
    return math.log(d1 / d2, 2)


def plot_path(name):
    os.makedirs(PLOT_DIR, exist_ok=True)
    return os.path.join(PLOT_DIR, name)


def pyplot():
    """matplotlib.pyplot with a non-interactive backend."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def mesh_study_axis(ax, ns, labels, xlabel, ylabel):
    """A mesh-convergence axis: log2 x with one tick per mesh, labelled, and the legend."""
    ax.set_xscale("log", base=2)
    ax.set_xticks(ns)
    ax.set_xticklabels(labels)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=8)


def save_figure(fig, path, title):
    """Titles, lays out, writes (110 dpi) and closes a figure."""
    if len(fig.axes) == 1:
        fig.axes[0].set_title(title)
    else:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    pyplot().close(fig)


def read_vtu(path):
    """Arrays of one fields/frame_NNNNN.vtu (fpmshell's base64 binary VTK XML, UInt64 headers):
    dict name -> list of tuples (or of floats for one component), plus 'points'."""
    import base64
    import re
    import struct
    text = open(path).read()
    out = {}
    pattern = (r'<DataArray type="(\w+)" Name="(\w+)"(?: NumberOfComponents="(\d+)")? '
               r'format="binary">\s*([A-Za-z0-9+/=]+)\s*</DataArray>')
    codes = {"Float64": "d", "Int64": "q", "UInt8": "B", "Int32": "i"}
    for typ, name, nc, data in re.findall(pattern, text):
        raw = base64.b64decode(data)
        nbytes = struct.unpack("<Q", raw[:8])[0]
        code = codes[typ]
        size = struct.calcsize(code)
        vals = list(struct.unpack("<%d%s" % (nbytes // size, code), raw[8:8 + nbytes]))
        k = int(nc) if nc else 1
        out[name] = vals if k == 1 else [tuple(vals[i:i + k]) for i in range(0, len(vals), k)]
    m = re.search(r'<Points>\s*<DataArray[^>]*format="binary">\s*([A-Za-z0-9+/=]+)', text)
    raw = base64.b64decode(m.group(1))
    nbytes = struct.unpack("<Q", raw[:8])[0]
    vals = struct.unpack("<%dd" % (nbytes // 8), raw[8:8 + nbytes])
    out["points"] = [tuple(vals[i:i + 3]) for i in range(0, len(vals), 3)]
    return out

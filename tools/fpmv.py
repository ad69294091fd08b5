"""Shared helpers of the verification/validation problem scripts (validation/<name>/run.py).

Protocol of a problem script (see validation/README.md):
    run.py --fpmshell PATH --out DIR [--quick]
runs fpmshell on its model(s), compares with the reference, writes DIR/rows.json (one row per
compared quantity, fields below), draws its plots (into docs/validation/ for the full variant,
into DIR/plots/ for the quick one), prints one line per row and a closing 'N passed, M failed'
line, and exits 0 only when every row passed.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PLOT_DIR = os.path.join(ROOT, "docs", "validation")
# Where plot_path() puts a plot: docs/validation/ for the full variant (make validate), the
# run's own --out folder for the quick one: make test writes nothing into the source tree (a
# clone may be read-only, and its tracked files stay as they were). tools/make_validation.py
# copies a quick variant's plots into docs/validation/ when its report shows that variant.
_plot_dir = PLOT_DIR


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
    args = ap.parse_args()
    global _plot_dir
    _plot_dir = os.path.join(os.path.abspath(args.out), "plots") if args.quick else PLOT_DIR
    return args


def start(problem, description, quick_cases, full_cases, extra=None):
    """The opening of a problem script: (args, cases, plot, plot_name): its options
    (parse_args), the cases (meshes) of the variant asked for, and the path and file name of its
    plot. The quick variant (make test) draws its own file, <problem>-quick.png, so that it
    keeps the full one."""
    args = parse_args(description, extra)
    plot = plot_path(problem + ("-quick" if args.quick else "") + ".png")
    return args, quick_cases if args.quick else full_cases, plot, os.path.basename(plot)


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


def run_or_reuse(args, model, out_dir, overrides, end_time, particles):
    """run() with one thread, unless --reuse was given and out_dir holds a completed run of
    this model to end_time with these particles (reusable)."""
    if args.reuse:
        got = reusable(out_dir, end_time, particles=particles)
        if got:
            return got
    return run(args.fpmshell, model, out_dir, overrides, threads=1)


def run_or_failure_row(args, model, out_dir, overrides, problem, mesh, rows):
    """run() with one thread; when fpmshell fails, prints why, appends a failed 'fpmshell run'
    row to rows and returns None (the problem goes on with its other meshes)."""
    try:
        return run(args.fpmshell, model, out_dir, overrides, threads=1)
    except RuntimeError as e:
        print(e)
        rows.append(row(problem, "fpmshell run", 0.0, 1.0, 0.0, mesh=mesh, relative=False,
                        note="fpmshell failed: see %s/log.txt" % out_dir))
        return None


def load_levels_row(problem, history, mesh, wall, plot):
    """The row of a relaxation run along a load path: every load level (the history's rows
    after the first) must have converged."""
    return row(problem, "converged load levels", len(history["time"]) - 1,
               int(sum(history["converged"][1:])), 0.0, mesh=mesh, wall=wall, plot=plot,
               relative=False, note="levels whose relaxation met control.tolerance")


def load_path_runs(args, problem, model, plot, rows, runs):
    """The relaxation runs of a problem along its load path, one per mesh of `runs` (mesh label,
    folder in --out, overrides): run_or_failure_row, then each run's 'converged load levels' row
    (load_levels_row); yields (mesh label, history, wall s) of each run that completed."""
    for mesh, folder, overrides in runs:
        got = run_or_failure_row(args, model, os.path.join(args.out, folder), overrides, problem,
                                 mesh, rows)
        if got is None:
            continue
        res, wall = got
        rows.append(load_levels_row(problem, res["history"], mesh, wall, plot))
        yield mesh, res["history"], wall


def strip_load_path_runs(args, problem, model, plot, rows, cases, overrides):
    """load_path_runs of a strip's cases (nx, ny, bending kernel, output interval), each run
    with overrides(nx, ny, bending, every), labelled '<nx>x<ny> right, <bending>'."""
    return load_path_runs(args, problem, model, plot, rows, [
        ("%dx%d right, %s" % (nx, ny, bending), "%s_%dx%d" % (bending, nx, ny),
         overrides(nx, ny, bending, every)) for nx, ny, bending, every in cases])


def end_load_overrides(per_node):
    """The --set overrides of an edge load given as loads 0 (every node of the edge), 1 and 2
    (its two corners, which take half of it: minus half there)."""
    return ["loads.0.value=[0, 0, %.17g]" % per_node,
            "loads.1.value=[0, 0, %.17g]" % (-0.5 * per_node),
            "loads.2.value=[0, 0, %.17g]" % (-0.5 * per_node)]


def reference_levels(history, reference):
    """The load levels of `reference` rows (t, values...) that the run computed, t = 0 left out:
    (index in the history, ' (level NOT converged)' or '', the row's values)."""
    for t, *values in reference:
        level = load_level(history, t) if t != 0 else None
        if level is not None:
            yield level[0], level[1], t, values


def load_level(history, t):
    """(index, flag) of the load level at load parameter t in the history of a relaxation run,
    flag ' (level NOT converged)' or ''; None when no level was computed at t."""
    k = [i for i, tt in enumerate(history["time"]) if abs(tt - t) < 1e-9]
    if not k:
        return None
    return k[0], "" if history["converged"][k[0]] else " (level NOT converged)"


def read_reference_csv(path):
    """A problem's reference table: CSV with '#' comment lines and one header line -> a list
    of tuples of floats, one per data line."""
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))][1:]
    return [tuple(float(x) for x in r) for r in rows]


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


def mesh_study(problem, quantity, reference, meshes, solve, tolerance, plot="", unit="",
               relative=True, tested=None):
    """The mesh-convergence loop of a problem script: one row per mesh, in the order of meshes.

    solve(mesh) runs fpmshell on one mesh and returns (value, wall, mesh_label, note, converged).
    The row of the finest mesh (the last), or of every mesh for which tested(mesh) is true, is
    tested with tolerance; the others are reported only. A relaxation that did not converge
    adds '; relaxation NOT converged' to the note and fails its row.
    Returns (rows, values) with values[mesh] = value."""
    rows, values = [], {}
    for mesh in meshes:
        value, wall, label, note, converged = solve(mesh)
        values[mesh] = value
        is_tested = tested(mesh) if tested else mesh == meshes[-1]
        r = row(problem, quantity, reference, value, tolerance if is_tested else None, mesh=label,
                wall=wall, plot=plot, relative=relative, unit=unit,
                note=note + ("" if converged else "; relaxation NOT converged"))
        if not converged:
            r["pass"] = False
        rows.append(r)
    return rows, values


def add_observed_order(rows, problem, quantity, meshes, values, plot, note,
                       not_monotone="; meshes not monotone, no observed order",
                       order=None):
    """Appends to rows the observed order of convergence of the three finest meshes (reported,
    not tested, against 2); values[mesh] as mesh_study returns them. When the three are not
    monotone there is no order: not_monotone (if any) is added to the note of the last row
    instead, so that rows.json holds no NaN. Nothing with fewer than three meshes.
    order(v1, v2, v3): the estimate, observed_order (element size halved) by default."""
    if len(meshes) < 3:
        return
    finest = meshes[-3:]
    p = (order or observed_order)(*[values[m] for m in finest])
    if math.isnan(p):
        if not_monotone:
            rows[-1]["note"] += not_monotone
    else:
        rows.append(row(problem, quantity, 2.0, p, None, mesh="%d/%d/%d" % tuple(finest),
                        plot=plot, note=note))


def kernel_studies(problem, quantity, reference, kernels, meshes, solve, tolerance, plot,
                   order_note, unit="", **order_options):
    """The mesh study of each bending kernel in turn: mesh_study with solve(kernel, mesh) and
    the row quantity '<quantity> <kernel>', then that kernel's observed order
    (add_observed_order, 'observed order <kernel>', note order_note; order_options:
    not_monotone, order). Returns (rows, results) with results[(kernel, mesh)] = value."""
    rows, results = [], {}
    for kernel in kernels:
        study, values = mesh_study(problem, "%s %s" % (quantity, kernel), reference, meshes,
                                   lambda mesh: solve(kernel, mesh), tolerance, plot=plot,
                                   unit=unit)
        rows += study
        results.update({(kernel, mesh): v for mesh, v in values.items()})
        add_observed_order(rows, problem, "observed order %s" % kernel, meshes, values, plot,
                           order_note, **order_options)
    return rows, results


def run_kernel(args, model, kernel, mesh, overrides):
    """A run of `model` with the bending kernel `kernel` (control.bending) on a mesh (its
    number of divisions, or a label such as 20x1), into <kernel>-<mesh> of --out, on one
    thread: (results, wall s)."""
    return run(args.fpmshell, model, os.path.join(args.out, "%s-%s" % (kernel, mesh)),
               list(overrides) + ["control.bending=" + kernel], threads=1)


def square_plate_study(problem, description, model, reference, note, reference_label, title,
                       kernels, meshes, tolerances, side):
    """The centre deflection of a square plate's quarter model under pressure (validation/
    plate_clamped, plate_simply_supported): its history `w_centre` on n x n meshes of the quarter
    (`meshes`: (quick, full)) for each bending kernel, against `reference` (m) with
    `tolerances` (quick, full), the observed orders, and the figure against the element size
    h / a (`side` a). Returns the script's exit status (finish)."""
    args, cases, plot, plot_name = start(problem, description, meshes[0], meshes[1])

    def solve(kernel, n):
        res, wall = run_kernel(args, model, kernel, n, ["mesh.nx=%d" % n, "mesh.ny=%d" % n])
        h = res["history"]
        return (-h["w_centre"][-1], wall, "quarter %dx%d (h=a/%d)" % (n, n, 2 * n), note,
                bool(h["converged"][-1]))

    rows, results = kernel_studies(
        problem, "w_centre", reference, kernels, cases, solve,
        tolerances[0] if args.quick else tolerances[1], plot_name,
        "log2((w1-w2)/(w2-w3)); report only (expected 2)", unit="m")
    draw_plate_deflection_study(
        plot, [side / (2 * n) for n in cases],
        [("fpmshell " + k, mark, [results[(k, n)] for n in cases])
         for k, mark in zip(kernels, ["o-", "s--"])],
        reference, reference_label, tolerances[1], title)
    return finish(args.out, rows)


def observed_order(w1, w2, w3):
    """Convergence order from three meshes, each halving the element size:
    log2((w1 - w2) / (w2 - w3)); nan when the sequence is not monotone."""
    d1, d2 = w1 - w2, w2 - w3
    if d2 == 0 or d1 / d2 <= 0:
        return float("nan")
    return math.log(d1 / d2, 2)


def write_grid_triangles(f, n_u, n_v, node, triangles):
    """The *ELEMENT, TYPE=S3 block of an Abaqus mesh file over a grid of n_u x n_v cells, the
    elements numbered from 1 in cell order: triangles(i, a, b, c, d) the cell's triangles, a ... d
    its corners node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)."""
    f.write("*ELEMENT, TYPE=S3\n")
    e = 0
    for j in range(n_v):
        for i in range(n_u):
            for t in triangles(i, node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)):
                e += 1
                f.write("%d, %d, %d, %d\n" % ((e,) + t))


def parabola_vertex(tm, w, i):
    """Extremum of the parabola through the samples i-1, i, i+1 of w(tm): (value, time), the
    peak independent of the output interval; the sample itself at either end of the record."""
    if i <= 0 or i >= len(w) - 1:
        return w[i], tm[i]
    t0, t1, t2 = tm[i - 1], tm[i], tm[i + 1]
    w0, w1, w2 = w[i - 1], w[i], w[i + 1]
    d01, d12 = (w1 - w0) / (t1 - t0), (w2 - w1) / (t2 - t1)
    a = (d12 - d01) / (t2 - t0)
    if a == 0:
        return w1, t1
    tv = min(max(0.5 * (t0 + t1) - d01 / (2 * a), t0), t2)
    # Newton form: w(t) = w0 + d01 (t - t0) + a (t - t0)(t - t1)
    return w0 + d01 * (tv - t0) + a * (tv - t0) * (tv - t1), tv


def fit_period(t, w, guess):
    """Period of the dominant harmonic of w(t): least-squares fit of C + a cos(wt) + b sin(wt),
    golden-section search of omega within +-30 % of 2 pi / guess."""
    import numpy as np
    t = np.asarray(t)
    w = np.asarray(w)

    def residual(om):
        m = np.column_stack([np.ones_like(t), np.cos(om * t), np.sin(om * t)])
        c, *_ = np.linalg.lstsq(m, w, rcond=None)
        return float(np.sum((m @ c - w) ** 2))

    om0 = 2 * math.pi / guess
    grid = np.linspace(0.7 * om0, 1.3 * om0, 241)
    res = [residual(o) for o in grid]
    k = int(np.argmin(res))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    g = (math.sqrt(5) - 1) / 2
    for _ in range(80):
        x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
        if residual(x1) < residual(x2):
            hi = x2
        else:
            lo = x1
    return float(2 * math.pi / (0.5 * (lo + hi)))


def plot_path(name):
    os.makedirs(_plot_dir, exist_ok=True)
    return os.path.join(_plot_dir, name)


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


def draw_plate_deflection_study(path, sizes, deflections, reference, reference_label, band,
                                 title):
    """The figure of a plate's centre deflection against the element size h / a: the values
    (in micrometres) beside the reference and its band (a relative tolerance), and their
    relative error on log axes with a slope-2 guide from the first series' coarsest error.
    deflections: list of (label, marker, values), one value per size."""
    plt = pyplot()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for label, mark, ws in deflections:
        ax1.plot(sizes, [w * 1e6 for w in ws], mark, label=label)
        ax2.loglog(sizes, [abs(w - reference) / reference for w in ws], mark, label=label)
    ax1.axhline(reference * 1e6, color="k", lw=1, label=reference_label)
    ax1.axhspan(reference * 1e6 * (1 - band), reference * 1e6 * (1 + band), color="0.85",
                label="$\\pm$%g %%" % (100 * band))
    ax1.set_xlabel("element size h / a")
    ax1.set_ylabel("centre deflection w [$\\mu$m]")
    ax1.set_xscale("log")
    ax1.legend(fontsize=8)
    if len(sizes) > 1:
        e0 = abs(deflections[0][2][0] - reference) / reference
        ax2.loglog(sizes, [e0 * (h / sizes[0])**2 for h in sizes], "k:", label="slope 2")
    ax2.set_xlabel("element size h / a")
    ax2.set_ylabel("relative error")
    ax2.legend(fontsize=8)
    save_figure(fig, path, title)


def figure(*args, **kwargs):
    """A figure and its axes: matplotlib's subplots (offscreen, pyplot())."""
    return pyplot().subplots(*args, **kwargs)


def label_axes(ax, xlabel, ylabel, legend_size=8, below=False, loc=None, grid=False,
               title=None):
    """The axes' labels, title and grid, and their legend (below: under the axes, in two
    columns; else at loc, matplotlib's best place by default)."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title)
    if grid:
        ax.grid(True, alpha=0.3)
    if below:
        ax.legend(fontsize=legend_size, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2)
    else:
        ax.legend(fontsize=legend_size, **({"loc": loc} if loc else {}))


def save_figure(fig, path, title, dpi=110):
    """Titles (the axes of a one-axes figure, else the figure; None: neither), lays out, writes
    and closes a figure."""
    if title is None:
        pass
    elif len(fig.axes) == 1:
        fig.axes[0].set_title(title)
    else:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    pyplot().close(fig)


def read_vtu(path):
    """Arrays of one fields/frame_NNNNN.vtu as fpmshell writes it (io/vtu_writer.hpp: raw
    appended data, zlib-compressed or not, base64 or ascii; UInt64 headers, little endian):
    dict name -> list of tuples (or of floats for one component), plus 'points'."""
    import base64
    import re
    import struct
    import zlib
    data = open(path, "rb").read()
    start = data.find(b'<AppendedData encoding="raw">')
    head = (data if start < 0 else data[:start]).decode()
    appended = data.index(b"_", start) + 1 if start >= 0 else -1
    zlib_blocks = 'compressor="vtkZLibDataCompressor"' in head
    codes = {"Float64": "d", "Int64": "q", "UInt8": "B", "Int32": "i"}

    def unpack(typ, raw):
        code = codes[typ]
        return list(struct.unpack("<%d%s" % (len(raw) // struct.calcsize(code), code), raw))

    def appended_bytes(offset):
        at = appended + offset
        if not zlib_blocks:
            n = struct.unpack("<Q", data[at:at + 8])[0]
            return data[at + 8:at + 8 + n]
        blocks = struct.unpack("<Q", data[at:at + 8])[0]
        sizes = struct.unpack("<%dQ" % blocks, data[at + 24:at + 24 + 8 * blocks])
        at += 24 + 8 * blocks
        raw = b""
        for size in sizes:
            raw += zlib.decompress(data[at:at + size])
            at += size
        return raw

    out = {}
    pattern = (r'<DataArray type="(\w+)" Name="(\w+)"(?: NumberOfComponents="(\d+)")? '
               r'format="(\w+)"(?: offset="(\d+)"/>|>([^<]*)</DataArray>)')
    for typ, name, nc, form, offset, body in re.findall(pattern, head):
        if name == "TimeValue":
            continue
        if form == "appended":
            vals = unpack(typ, appended_bytes(int(offset)))
        elif form == "binary":
            raw = base64.b64decode(body.strip())
            vals = unpack(typ, raw[8:8 + struct.unpack("<Q", raw[:8])[0]])
        else:
            vals = [float(v) if typ == "Float64" else int(v) for v in body.split()]
        k = int(nc) if nc else 1
        rows = vals if k == 1 else [tuple(vals[i:i + k]) for i in range(0, len(vals), k)]
        out["points" if name == "Points" else name] = rows
    return out

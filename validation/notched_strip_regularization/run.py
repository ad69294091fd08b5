#!/usr/bin/env python3
"""The element-size regularization of a failure strain (theory.md eq. 7.6-3, GISSMO's LCREGD):
a necking strip calibrated, a notched strip predicted, on three meshes.

A steel strip (power law k = 530 MPa, n = 0.2; thickness following plane stress) necks, and
past the neck the strain of the band grows as 1/(element size): a failure strain alone makes
the fracture mesh-dependent. Calibration (specimen A: a smooth 2 % narrowing over 4 mm): without
failure, the neck's plastic strain eps(l) at t* = 5 ms on each mesh of element size l; the
finest mesh's is the failure strain eps_f, and r(l) = eps(l) / eps_f the regularization curve.
Prediction (specimen B: a notch 10 % deep over 5 mm, another geometry): pulled to fracture with
failure: {tabulated: {failure_strain: eps_f, regularization: r(l)}} on the same meshes, and
without the regularization. Fracture: the stretch where the force falls below half its peak.
See README.md. Protocol: validation/README.md.
"""
import math
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import fpmv  # noqa: E402

PROBLEM = "notched_strip_regularization"
L, W = 0.05, 0.01                  # strip length and width
SPECIMENS = {"A": (0.02, 0.004),   # smooth narrowing: depth (fraction of W), length scale
             "B": (0.10, 0.005)}   # the notch
T_CALIBRATION = 0.005              # t*: the neck well past its onset (about 3.5 ms) on every mesh
# Tolerances (reasons):
# - fracture stretch of B on a coarser mesh vs the finest, regularized: 10 %. The size-only
#   regularization carries the band's 1/l growth from A to B but not B's earlier localization
#   (its neck forms at a smaller stretch than A's, so B's band has grown less at fracture and
#   r(l) calibrated on A over-corrects a little); GISSMO users accept regularization curves
#   within this band. Measured: 5.2 % (2.5 mm) and 3.2 % (1.25 mm) against 0.625 mm.
TOL_FRACTURE = 0.10
# - energy balance: < 1 % on every dynamic problem (docs/benchmarks.md, criteria).
TOL_ENERGY = 0.01


def write_mesh(path, nx, ny, depth, scale):
    """nx x ny squares, two triangles each; node sets fixed_end (x = 0) and pulled_end."""
    nodes = []
    for j in range(ny + 1):
        for i in range(nx + 1):
            x = L * i / nx
            narrowing = 1 - depth * math.exp(-((x - L / 2) / scale) ** 2)
            nodes.append((x, (W * j / ny - W / 2) * narrowing))
    with open(path, "w") as f:
        f.write("*KEYWORD\n*NODE\n")
        for k, (x, y) in enumerate(nodes):
            f.write("%8d%16.9e%16.9e%16.9e\n" % (k + 1, x, y, 0.0))
        f.write("*ELEMENT_SHELL\n")
        e = 0
        for j in range(ny):
            for i in range(nx):
                a = j * (nx + 1) + i + 1
                for tri in ((a, a + 1, a + nx + 2), (a, a + nx + 2, a + nx + 1)):
                    e += 1
                    f.write("%8d%8d%8d%8d%8d%8d\n" % (e, 1, tri[0], tri[1], tri[2], tri[2]))
        for sid, name, col in ((1, "fixed_end", 0), (2, "pulled_end", nx)):
            ids = [j * (nx + 1) + col + 1 for j in range(ny + 1)]
            f.write("*SET_NODE_LIST_TITLE\n%s\n%10d\n" % (name, sid))
            for k in range(0, len(ids), 8):
                f.write("".join("%10d" % v for v in ids[k:k + 8]) + "\n")
        f.write("*END\n")


def prepare(out_dir, nx, ny, specimen, failure=""):
    """The run folder: the mesh and strip.yaml with the material's `failure` (a flow-map
    entry); returns the model's path."""
    os.makedirs(out_dir, exist_ok=True)
    write_mesh(os.path.join(out_dir, "mesh.k"), nx, ny, *SPECIMENS[specimen])
    text = open(os.path.join(HERE, "strip.yaml")).read()
    if failure:
        text = text.replace("yield_stress: 2.0e8}", "yield_stress: 2.0e8,\n          failure: %s}"
                            % failure)
    model = os.path.join(out_dir, "model.yaml")
    with open(model, "w") as f:
        f.write(text)
    return model


def neck_strain(frame_path):
    """The largest mid-surface plastic strain of the elements within 10 mm of mid-length."""
    v = fpmv.read_vtu(frame_path)
    pts, con, disp = v["points"], v["connectivity"], v["displacement"]
    best = 0.0
    for c, eps in enumerate(v["plastic_strain_middle"]):
        x0 = sum(pts[con[3 * c + i]][0] - disp[con[3 * c + i]][0] for i in range(3)) / 3
        if abs(x0 - L / 2) < 0.01:
            best = max(best, eps)
    return best


def fracture(history):
    """(stretch where the force first falls below half its peak, peak force), or (None, peak)."""
    force = [-f for f in history["force"]]
    peak = max(force)
    for u, f in zip(history["stretch"], force):
        if u > 1e-3 and f < 0.5 * peak:
            return u, peak
    return None, peak


def main():
    args, meshes, plot, plot_name = fpmv.start(
        PROBLEM, __doc__, [(20, 4), (40, 8)], [(20, 4), (40, 8), (80, 16)])
    rows = []
    size = {m: L / m[0] for m in meshes}  # sqrt(2 A_0) of the triangles: the square's side
    # calibration on A
    eps = {}
    for m in meshes:
        out = os.path.join(args.out, "A-%dx%d" % m)
        model = prepare(out, m[0], m[1], "A")
        res, wall = fpmv.run(args.fpmshell, model, out, ["control.end_time=%g" % T_CALIBRATION])
        eps[m] = neck_strain(os.path.join(out, "fields", "frame_00001.vtu"))
        rows.append(fpmv.row(PROBLEM, "A: neck strain at t* (calibration)", eps[meshes[-1]]
                             if m == meshes[-1] else eps[m], eps[m], None,
                             mesh="%dx%d" % m, wall=wall, plot=plot_name,
                             note="report only: r(l) = this / the finest mesh's"))
    eps_f = eps[meshes[-1]]
    points = sorted((size[m], eps[m] / eps_f) for m in meshes)
    regularization = "[" + ", ".join("[%.6g, %.6g]" % p for p in points) + "]"
    # prediction on B, regularized and not
    curves, fractures = {}, {}
    for kind in ("regularized", "raw"):
        failure = ("{tabulated: {failure_strain: [[0, %.6g]]%s}, points: 1}"
                   % (eps_f, ", regularization: " + regularization if kind == "regularized" else ""))
        for m in meshes:
            out = os.path.join(args.out, "B-%s-%dx%d" % (kind, m[0], m[1]))
            shutil.rmtree(out, ignore_errors=True)
            res, wall = fpmv.run(args.fpmshell, prepare(out, m[0], m[1], "B", failure), out)
            h = res["history"]
            curves[(kind, m)] = (h["stretch"], [-f for f in h["force"]])
            fractures[(kind, m)] = fracture(h)[0]
            rows.append(fpmv.row(PROBLEM, "B %s: energy balance error" % kind, 0.0,
                                 res["summary"]["energy_error"], TOL_ENERGY, mesh="%dx%d" % m,
                                 wall=wall, plot=plot_name, relative=False))
    finest = meshes[-1]
    for m in meshes[:-1]:
        for kind in ("regularized", "raw"):
            ref, got = fractures[(kind, finest)], fractures[(kind, m)]
            rows.append(fpmv.row(
                PROBLEM, "B %s: fracture stretch vs the finest mesh's" % kind, ref,
                got if got is not None else float("nan"),
                TOL_FRACTURE if kind == "regularized" else None, mesh="%dx%d" % m, plot=plot_name,
                note=("r(l) calibrated on A" if kind == "regularized" else
                      "report only: the mesh dependence the regularization removes")))
    draw(plot, meshes, curves)
    return fpmv.finish(args.out, rows)


def draw(path, meshes, curves):
    fig, ax = fpmv.figure(figsize=(7, 4.5))
    colours = ["tab:blue", "tab:orange", "tab:green"]
    for c, m in zip(colours, meshes):
        for kind, style in (("regularized", "-"), ("raw", ":")):
            u, f = curves[(kind, m)]
            # to just past the fracture (the halves ring on afterwards, undamped)
            end = next((k for k in range(len(f)) if u[k] > 1e-3 and f[k] < 0.05 * max(f)), len(f))
            u, f = u[:end + 1], f[:end + 1]
            ax.plot([1e3 * x for x in u], [1e-3 * x for x in f], style, color=c,
                    label="%s, %.3g mm elements" % (kind, 1e3 * L / m[0]))
    fpmv.label_axes(ax, "stretch [mm]", "force [kN]")
    ax.grid(alpha=0.3)
    fpmv.save_figure(fig, path, "Notched strip to fracture: regularized (calibrated on a "
                     "smooth strip) and not")


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Slit annular plate under a lifting line force (Sze, Liu & Lo 2004, problem 3.3; benchmarks.md 4).

Runs fpmshell in relaxation mode along q/qmax = 0..1 and compares the lift of the inner (A, r = 6)
and outer (B, r = 10) corner of the loaded slit edge with Sze's table at every computed level,
plots the whole path and writes rows.json. Protocol: validation/README.md.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools"))
import fpmv  # noqa: E402

PROBLEM = "slit_annular_plate"
Q_MAX = 0.8
WIDTH = 4.0  # R_o - R_i
TOL = 0.02   # done-criterion of benchmarks.md: the path within 2 % of Sze's table

# (divisions_radial, divisions_angle, bending, membrane, load-level spacing, tolerance or None,
# why).
QUICK = [(4, 32, "dkt", "cst", 0.5, 0.07,
          "CST, coarse 4x32 mesh: measured error -5.4 % (w_A) / -4.2 % (w_B), the membrane "
          "locking of README.md; 7 % bounds it (a regression check, not the 2 % criterion)"),
         (4, 32, "dkt", "smoothed", 0.5, 0.03,
          "smoothed membrane, coarse 4x32 mesh: measured -2.0 % / -1.8 %, decreasing with "
          "refinement (8x64: -1.4 %); 3 % bounds the coarse mesh")]
FULL = [(4, 32, "dkt", "cst", 0.25, None, "CST, coarse mesh: reported, not tested"),
        (8, 64, "dkt", "cst", 0.5, None,
         "CST: locks on the twisted facets (README.md), -3 to -4 %; reported, not tested"),
        (4, 32, "bciz", "cst", 0.5, None, "BCIZ, CST, coarse mesh: reported, not tested"),
        (4, 32, "dkt", "smoothed", 0.5, None, "smoothed membrane, coarse mesh: reported"),
        (8, 64, "dkt", "smoothed", 0.5, TOL,
         "done-criterion of benchmarks.md: 2 % of Sze's table (smoothed membrane)")]


def overrides(nr, na, bending, membrane, every):
    per_node = Q_MAX * WIDTH / nr  # q x tributary length; the corners get half
    return ["mesh.divisions_radial=%d" % nr, "mesh.divisions_angle=%d" % na,
            "control.bending=%s" % bending, "control.membrane=%s" % membrane,
            "output.every=%g" % every] + fpmv.end_load_overrides(per_node)


def main():
    args, cases, plot, _ = fpmv.start(PROBLEM, __doc__, QUICK, FULL)
    ref = fpmv.read_reference_csv(os.path.join(HERE, "reference.csv"))
    rows, runs = [], []
    tolerances = {}  # per mesh label: the case's tolerance and its reason
    runs_asked = []
    for nr, na, bending, membrane, every, tol, why in cases:
        mesh = "%dx%d right, %s, %s membrane" % (nr, na, bending, membrane)
        tolerances[mesh] = (tol, why)
        runs_asked.append((mesh, "%s_%s_%dx%d" % (bending, membrane, nr, na),
                           overrides(nr, na, bending, membrane, every)))
    for mesh, h, wall in fpmv.load_path_runs(args, PROBLEM, os.path.join(HERE, "model.yaml"),
                                             plot, rows, runs_asked):
        tol, why = tolerances[mesh]
        runs.append((mesh, h))
        for i, flag, t, (wa, wb) in fpmv.reference_levels(h, ref):
            for name, val, r in (("w_A (r = 6)", h["w_a"][i], wa), ("w_B (r = 10)", h["w_b"][i], wb)):
                rows.append(fpmv.row(PROBLEM, "%s at q/qmax = %.2f" % (name, t), r, val, tol,
                                     mesh=mesh, wall=wall, plot=plot, note=why + flag))
    draw(plot, ref, runs)
    return fpmv.finish(args.out, rows)


def draw(path, ref, runs):
    fig, ax = fpmv.figure(figsize=(7, 5))
    t = [r[0] * Q_MAX for r in ref]
    ax.plot([r[1] for r in ref], t, "ko", mfc="none", label="Sze et al. 2004 (S4R 10x80): w_A")
    ax.plot([r[2] for r in ref], t, "ks", mfc="none", label="Sze et al. 2004 (S4R 10x80): w_B")
    for (mesh, h), c in zip(runs, ["C0", "C1", "C2", "C3", "C4", "C5"]):
        q = [x * Q_MAX for x in h["time"]]
        # equilibrium points only at the computed levels: thin lines just link them
        ax.plot(h["w_a"], q, "-", color=c, lw=0.7, marker="o", ms=5, label="fpmshell %s" % mesh)
        ax.plot(h["w_b"], q, "--", color=c, lw=0.7, marker="s", ms=5)
    fpmv.label_axes(ax, "lift of the loaded edge: w_A at r = 6 (solid), w_B at r = 10 (dashed)",
                    "line force q", loc="lower right", grid=True)
    fpmv.save_figure(fig, path, "Slit annular plate under a lifting line force", dpi=120)


if __name__ == "__main__":
    sys.exit(main())

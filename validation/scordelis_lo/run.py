#!/usr/bin/env python3
"""Scordelis-Lo roof: vertical deflection at the mid-span free edge under self-weight.

Quarter model (model.yaml) on 4x4 ... 32x32 meshes with the BCIZ and DKT bending kernels,
observed order of convergence. The load is applied at 1/1000 (linear response, see
model.yaml) and the deflection scaled back. See README.md. Protocol: validation/README.md.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import fpmv  # noqa: E402

PROBLEM = "scordelis_lo"
R, L_HALF, ANGLE, G = 25.0, 25.0, math.radians(40.0), 90.0     # quarter model, model.yaml
TOTAL = G * R * ANGLE * L_HALF          # full self-weight of the quarter (39 269.9)
W_REF = 0.3024          # MacNeal & Harder (1985), deep shell theory value used by most papers
W_KIRCHHOFF = 0.3006    # converged Kirchhoff-Love value (drawn, not tested)

KERNELS = ["bciz", "dkt"]
MESHES_FULL = [4, 8, 16, 32]     # divisions of the quarter (arc x length)
MESHES_QUICK = [16]
# Finest mesh (32x32 on the quarter): 2 %, the benchmark's criterion. CST membranes in
# facets converge slowly on this membrane-bending problem; the 32x32 error is about 1.4 %
# and the extrapolated limit is within 0.3 % of 0.3024 (README.md).
TOL_FINE = 0.02
# Quick, 16x16: its measured discretisation error is 4.1 % (BCIZ) / 4.4 % (DKT), from below,
# as expected from the 8/16/32 sequence; 6 % leaves that error and flags any regression
# that changes the answer by more than a couple of per cent.
TOL_QUICK = 0.06


def force_overrides(n):
    """Per-node self-weight for an n x n mesh: a full cell on every node, minus half a cell on
    the boundary, minus a quarter cell at each corner (model.yaml loads 0..5)."""
    f = G * (R * ANGLE / n) * (L_HALF / n)
    ov = ["mesh.divisions_arc=%d" % n, "mesh.divisions_length=%d" % n,
          "loads.0.value=[0,0,%.12g]" % -f, "loads.1.value=[0,0,%.12g]" % (f / 2)]
    ov += ["loads.%d.value=[0,0,%.12g]" % (i, f / 4) for i in range(2, 6)]
    return ov


def main():
    args, meshes, plot, plot_name = fpmv.start(PROBLEM, __doc__, MESHES_QUICK, MESHES_FULL)
    model = os.path.join(HERE, "model.yaml")

    def solve(kernel, n):
        res, wall = fpmv.run_kernel(args, model, kernel, n, force_overrides(n))
        h = res["history"]
        applied = -h["fz"][-1]
        w = -h["w_a"][-1] * TOTAL / applied        # linear: scale to the full self-weight
        return (w, wall, "quarter %dx%d" % (n, n),
                "MacNeal-Harder 0.3024; load x%.3g, scaled" % (applied / TOTAL),
                bool(h["converged"][-1]))

    rows, results = fpmv.kernel_studies(
        PROBLEM, "w free edge mid-span", W_REF, KERNELS, meshes, solve,
        TOL_QUICK if args.quick else TOL_FINE, plot_name, "log2((w1-w2)/(w2-w3)); report only")
    draw(plot, meshes, results)
    return fpmv.finish(args.out, rows)


def draw(path, meshes, results):
    fig, (ax1, ax2) = fpmv.figure(1, 2, figsize=(10, 4))
    for kernel, mark in zip(KERNELS, ["o-", "s--"]):
        ws = [results[(kernel, n)] for n in meshes]
        ax1.plot(meshes, ws, mark, label="fpmshell " + kernel)
        ax2.loglog(meshes, [abs(w - W_REF) / W_REF for w in ws], mark, label="fpmshell " + kernel)
    ax1.axhline(W_REF, color="k", lw=1, label="reference 0.3024")
    ax1.axhline(W_KIRCHHOFF, color="k", lw=1, ls=":", label="Kirchhoff-Love 0.3006")
    ax1.axhspan(W_REF * (1 - TOL_FINE), W_REF * (1 + TOL_FINE), color="0.85", label="$\\pm$2 %")
    ax1.set_xscale("log", base=2)
    fpmv.label_axes(ax1, "divisions per side of the quarter", "mid-span free-edge deflection")
    if len(meshes) > 1:
        e0 = abs(results[("bciz", meshes[0])] - W_REF) / W_REF
        ax2.loglog(meshes, [e0 * (meshes[0] / n)**2 for n in meshes], "k:", label="slope 2")
    fpmv.label_axes(ax2, "divisions per side of the quarter", "relative error")
    fpmv.save_figure(fig, path, "Scordelis-Lo roof (quarter model), linear response")


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Pinched cylinder with rigid diaphragms: radial deflection under the load.

1/8 model (model.yaml) on 8x8 ... 32x32 meshes with the BCIZ and DKT bending kernels, observed
order of convergence. See README.md. Protocol: validation/README.md.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import fpmv  # noqa: E402

PROBLEM = "pinched_cylinder"
W_REF = 1.8248e-5       # Belytschko et al. (1985), thin shell (Flügge series), P = 1

KERNELS = ["bciz", "dkt"]
MESHES_FULL = [8, 16, 24, 32]    # divisions of the 1/8 model (arc x length)
MESHES_QUICK = [16]
# Finest mesh (32x32): 2 %, the benchmark's criterion. The meshes converge (non-monotonically
# near the end) to about 1.3 % (BCIZ) / 0.6 % (DKT) above the thin-shell reference; 2 % holds
# that offset of the Kirchhoff-type facets plus the remaining 32x32 discretisation error.
TOL_FINE = 0.02
# Quick, 16x16: 4 %. Measured: 1.1 % (BCIZ) / 0.6 % (DKT) below the reference; the values
# converge to about 1.3 % / 0.6 % above it (BCIZ 48x48: 1.8481e-5), so the 16x16 error is the
# sum of a -2.4 % discretisation error and that offset; 4 % holds both with a margin and still
# catches any regression of the boundary conditions (the old symmetry treatment gave +10 %).
TOL_QUICK = 0.04


def observed_order(w1, w2, w3, r1, r2):
    """Order p from three meshes, refinement ratios r1 = h1/h2 and r2 = h2/h3: solves
    (w1 - w2) / (w2 - w3) = r2^p (r1^p - 1) / (r2^p - 1) by bisection; nan if not monotone."""
    d1, d2 = w1 - w2, w2 - w3
    if d2 == 0 or d1 / d2 <= 0:
        return float("nan")
    ratio = d1 / d2
    f = lambda p: r2**p * (r1**p - 1) / (r2**p - 1) - ratio  # noqa: E731
    lo, hi = 0.01, 20.0
    if f(lo) * f(hi) > 0:
        return float("nan")
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def main():
    args, meshes, plot, plot_name = fpmv.start(PROBLEM, __doc__, MESHES_QUICK, MESHES_FULL)
    model = os.path.join(HERE, "model.yaml")

    def solve(kernel, n):
        res, wall = fpmv.run_kernel(args, model, kernel, n,
                                    ["mesh.divisions_arc=%d" % n, "mesh.divisions_length=%d" % n])
        h = res["history"]
        return (-h["w_load"][-1], wall, "1/8 %dx%d" % (n, n),
                "Belytschko et al. 1985: 1.8248e-5", bool(h["converged"][-1]))

    m = meshes[-3:]  # the observed order: refinement ratios of the three finest meshes
    rows, results = fpmv.kernel_studies(
        PROBLEM, "w under the load", W_REF, KERNELS, meshes, solve,
        TOL_QUICK if args.quick else TOL_FINE, plot_name,
        "from the three finest meshes; report only",
        not_monotone="; %d/%d/%d not monotone, no observed order" % tuple(m) if len(m) == 3 else "",
        order=lambda w1, w2, w3: observed_order(w1, w2, w3, m[1] / m[0], m[2] / m[1]))
    draw(plot, meshes, results)
    return fpmv.finish(args.out, rows)


def draw(path, meshes, results):
    fig, ax = fpmv.figure(figsize=(6, 4))
    for kernel, mark in zip(KERNELS, ["o-", "s--"]):
        ax.plot(meshes, [results[(kernel, n)] / W_REF for n in meshes], mark,
                label="fpmshell " + kernel)
    ax.axhline(1.0, color="k", lw=1, label="reference 1.8248e-5")
    ax.axhspan(1 - TOL_FINE, 1 + TOL_FINE, color="0.85", label="$\\pm$2 %")
    fpmv.label_axes(ax, "divisions per side of the 1/8 model", "w under the load / reference")
    fpmv.save_figure(fig, path, "Pinched cylinder with rigid diaphragms (1/8 model)")


if __name__ == "__main__":
    sys.exit(main())

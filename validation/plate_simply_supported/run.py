#!/usr/bin/env python3
"""Simply supported square plate under uniform pressure: centre deflection vs Navier's series.

Quarter model (model.yaml), 3 meshes, BCIZ and DKT bending kernels, observed order of
convergence. See README.md. Protocol: validation/README.md.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import fpmv  # noqa: E402

PROBLEM = "plate_simply_supported"
E, NU, H, A, Q = 2.1e11, 0.3, 0.01, 1.0, 100.0      # model.yaml (a = full side)
D = E * H**3 / (12 * (1 - NU**2))


def navier_coefficient(terms=400):
    """w_centre / (q a^4 / D) of the simply supported square plate (Navier double series;
    Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed., section 30 and
    Table 8: 0.00406). Converged to 1e-9 with 400 terms."""
    s = 0.0
    for m in range(1, terms, 2):
        for n in range(1, terms, 2):
            s += (-1) ** ((m + n) // 2 - 1) / (m * n * (m * m + n * n) ** 2)
    return 16.0 / math.pi**6 * s


COEF = navier_coefficient()          # 0.00406235
W_REF = COEF * Q * A**4 / D

KERNELS = ["bciz", "dkt"]
MESHES_FULL = [4, 8, 16]      # divisions per side of the quarter (element size a/8 ... a/32)
MESHES_QUICK = [8]
# Finest mesh (16x16 on the quarter, h = a/32): 2 %, the benchmark's convergence criterion.
# The discretisation error there is 0.3 % (BCIZ) and 0.01 % (DKT); the 4x4 mesh is already
# within 1 %, so 2 % is loose for this problem and mainly guards against regressions.
TOL_FINE = 0.02
# Quick, 8x8 quarter (h = a/16): error 0.5 % (BCIZ) / 0.04 % (DKT); the same 2 % applies
# (a wrong kernel or boundary condition moves w by tens of per cent).
TOL_QUICK = 0.02


def centre_w(res):
    h = res["history"]
    return -h["w_centre"][-1], bool(h["converged"][-1])


def main():
    args, meshes, plot, plot_name = fpmv.start(PROBLEM, __doc__, MESHES_QUICK, MESHES_FULL)
    model = os.path.join(HERE, "model.yaml")

    def solve(kernel, n):
        out = os.path.join(args.out, "%s-%d" % (kernel, n))
        res, wall = fpmv.run(args.fpmshell, model, out,
                             ["mesh.nx=%d" % n, "mesh.ny=%d" % n, "control.bending=" + kernel],
                             threads=1)
        w, conv = centre_w(res)
        return (w, wall, "quarter %dx%d (h=a/%d)" % (n, n, 2 * n),
                "%.8f q a^4/D (Navier)" % COEF, conv)

    rows, results = fpmv.kernel_studies(
        PROBLEM, "w_centre", W_REF, KERNELS, meshes, solve, TOL_QUICK if args.quick else TOL_FINE,
        plot_name, "log2((w1-w2)/(w2-w3)); report only (expected 2)", unit="m")
    draw(plot, meshes, results)
    return fpmv.finish(args.out, rows)


def draw(path, meshes, results):
    fpmv.draw_plate_deflection_study(
        path, [A / (2 * n) for n in meshes],
        [("fpmshell " + k, mark, [results[(k, n)] for n in meshes])
         for k, mark in zip(KERNELS, ["o-", "s--"])],
        W_REF, "Navier %.6f qa$^4$/D" % COEF, TOL_FINE,
        "Simply supported square plate, uniform pressure (quarter model)")


if __name__ == "__main__":
    sys.exit(main())

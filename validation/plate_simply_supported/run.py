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


def main():
    return fpmv.square_plate_study(
        PROBLEM, __doc__, os.path.join(HERE, "model.yaml"), W_REF,
        "%.8f q a^4/D (Navier)" % COEF, "Navier %.6f qa$^4$/D" % COEF,
        "Simply supported square plate, uniform pressure (quarter model)", KERNELS,
        (MESHES_QUICK, MESHES_FULL), (TOL_QUICK, TOL_FINE), A)


if __name__ == "__main__":
    sys.exit(main())

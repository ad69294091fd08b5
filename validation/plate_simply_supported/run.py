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
    args = fpmv.parse_args(__doc__)
    meshes = MESHES_QUICK if args.quick else MESHES_FULL
    model = os.path.join(HERE, "model.yaml")
    # the quick variant (make test) draws its own file so that it keeps the full one
    plot = fpmv.plot_path(PROBLEM + ("-quick" if args.quick else "") + ".png")
    plot_name = os.path.basename(plot)
    rows, results = [], {}
    for kernel in KERNELS:
        for n in meshes:
            out = os.path.join(args.out, "%s-%d" % (kernel, n))
            res, wall = fpmv.run(args.fpmshell, model, out,
                                 ["mesh.nx=%d" % n, "mesh.ny=%d" % n, "control.bending=" + kernel],
                                 threads=1)
            w, conv = centre_w(res)
            results[(kernel, n)] = w
            finest = n == meshes[-1]
            tol = (TOL_QUICK if args.quick else TOL_FINE) if finest else None
            r = fpmv.row(PROBLEM, "w_centre %s" % kernel, W_REF, w, tol,
                         mesh="quarter %dx%d (h=a/%d)" % (n, n, 2 * n), wall=wall, plot=plot_name,
                         note="%.8f q a^4/D (Navier)" % COEF + ("" if conv else "; relaxation NOT converged"),
                         unit="m")
            if not conv:
                r["pass"] = False
            rows.append(r)
        if len(meshes) == 3:
            p = fpmv.observed_order(*[results[(kernel, n)] for n in meshes])
            if math.isnan(p):     # not monotone: no order (and no NaN in rows.json)
                rows[-1]["note"] += "; meshes not monotone, no observed order"
            else:
                rows.append(fpmv.row(PROBLEM, "observed order %s" % kernel, 2.0, p, None,
                                     mesh="%d/%d/%d" % tuple(meshes), plot=plot_name,
                                     note="log2((w1-w2)/(w2-w3)); report only (expected 2)"))

    draw(plot, meshes, results)
    return fpmv.finish(args.out, rows)


def draw(path, meshes, results):
    plt = fpmv.pyplot()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    hs = [A / (2 * n) for n in meshes]
    for kernel, mark in zip(KERNELS, ["o-", "s--"]):
        ws = [results[(kernel, n)] for n in meshes]
        ax1.plot(hs, [w * 1e6 for w in ws], mark, label="fpmshell " + kernel)
        ax2.loglog(hs, [abs(w - W_REF) / W_REF for w in ws], mark, label="fpmshell " + kernel)
    ax1.axhline(W_REF * 1e6, color="k", lw=1, label="Navier %.6f qa$^4$/D" % COEF)
    ax1.axhspan(W_REF * 1e6 * (1 - TOL_FINE), W_REF * 1e6 * (1 + TOL_FINE), color="0.85",
                label="$\\pm$2 %")
    ax1.set_xlabel("element size h / a")
    ax1.set_ylabel("centre deflection w [$\\mu$m]")
    ax1.set_xscale("log")
    ax1.legend(fontsize=8)
    if len(hs) > 1:
        e0 = abs(results[("bciz", meshes[0])] - W_REF) / W_REF
        ax2.loglog(hs, [e0 * (h / hs[0])**2 for h in hs], "k:", label="slope 2")
    ax2.set_xlabel("element size h / a")
    ax2.set_ylabel("relative error")
    ax2.legend(fontsize=8)
    fig.suptitle("Simply supported square plate, uniform pressure (quarter model)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())

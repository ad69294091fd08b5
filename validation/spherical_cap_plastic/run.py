#!/usr/bin/env python3
"""Shallow spherical cap under a suddenly applied pressure, elastic-plastic (benchmarks.md 5.1).

Full cap (model.yaml: sigma_y = 24 000 psi, E_t = 0.21e6 psi, bilinear isotropic) with 127, 469,
631, 1261 and 2437 particles (the paper's models I-III and two finer ones), plus the elastic
cap on the finest mesh for comparison; apex deflection history. See README.md.
Protocol: validation/README.md.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import fpmv  # noqa: E402

PROBLEM = "spherical_cap_plastic"
PARTICLES = {6: 127, 12: 469, 14: 631, 20: 1261, 28: 2437}
RINGS_FULL = [6, 12, 14, 20, 28]
RINGS_QUICK = [12]
END_QUICK = 0.6e-3     # first large peak (about 0.45 ms) and the first rebound (about 0.6 ms)
# Tested (benchmarks.md 5.1 and issue 3): after the first peak the apex stays below zero (a
# permanent downward set; the elastic cap rebounds to +0.043 in), and the energy balance closes
# within 1 %. No published elastic-plastic curve could be read here (see README.md): the peak
# values are reported, not tested.
TOL_ENERGY = 0.01
# The permanent set is the mean apex deflection from 0.6 ms to the end (about one period of
# the residual oscillation); reported.


def analyse(t, w):
    tm = [x * 1e3 for x in t]
    idx = [i for i, x in enumerate(tm) if x <= 0.55]
    i = min(idx, key=lambda k: w[k])
    after = [w[k] for k in range(len(tm)) if tm[k] > tm[i]]
    late = [(tm[k], w[k]) for k in range(len(tm)) if tm[k] >= 0.6]
    out = {"peak": (w[i], tm[i]), "max_after": max(after) if after else 0.0}
    if len(late) > 2:
        span = late[-1][0] - late[0][0]
        out["set"] = sum(0.5 * (late[k][1] + late[k + 1][1]) * (late[k + 1][0] - late[k][0])
                         for k in range(len(late) - 1)) / span
    return out


def main():
    args = fpmv.parse_args(__doc__)
    rings = RINGS_QUICK if args.quick else RINGS_FULL
    model = os.path.join(HERE, "model.yaml")
    elastic_model = os.path.join(HERE, "..", "spherical_cap_elastic", "model.yaml")
    plot = fpmv.plot_path(PROBLEM + ("-quick" if args.quick else "") + ".png")
    plot_name = os.path.basename(plot)
    rows, curves = [], {}
    finest = rings[-1]
    ov_end = ["control.end_time=%g" % END_QUICK] if args.quick else []
    el, wall_el = fpmv.run(args.fpmshell, elastic_model, os.path.join(args.out, "elastic-%d" % finest),
                           ["mesh.divisions=%d" % finest] + ov_end, threads=1)
    curves["elastic %d rings" % finest] = (el["history"]["time"], el["history"]["apex_w"])
    el_peak = analyse(el["history"]["time"], el["history"]["apex_w"])["peak"]
    for n in rings:
        res, wall = fpmv.run(args.fpmshell, model, os.path.join(args.out, "plastic-%d" % n),
                             ["mesh.divisions=%d" % n] + ov_end, threads=1)
        t, w = res["history"]["time"], res["history"]["apex_w"]
        curves["elastic-plastic %d rings" % n] = (t, w)
        a = analyse(t, w)
        mesh = "%d rings, %d particles, bciz" % (n, PARTICLES[n])
        tested = n == finest
        r = fpmv.row(PROBLEM, "apex stays below zero after the first peak (max uz)", 0.0,
                     a["max_after"], None, mesh=mesh, wall=wall, plot=plot_name, relative=False,
                     unit="in", note="passes when < 0 (the elastic cap rebounds to +0.043 in)")
        if tested:
            r["tolerance"] = 0.0
            r["pass"] = a["max_after"] < 0
        rows.append(r)
        rows.append(fpmv.row(PROBLEM, "first large peak apex w", el_peak[0], a["peak"][0], None,
                             mesh=mesh, wall=wall, plot=plot_name, unit="in",
                             note="reference: the elastic cap on %d rings; report only" % finest))
        rows.append(fpmv.row(PROBLEM, "first large peak time", el_peak[1], a["peak"][1], None,
                             mesh=mesh, wall=wall, plot=plot_name, unit="ms",
                             note="reference: the elastic cap; report only"))
        if "set" in a:
            rows.append(fpmv.row(PROBLEM, "permanent set (mean apex w, 0.6 ms to end)", 0.0,
                                 a["set"], None, mesh=mesh, wall=wall, plot=plot_name,
                                 relative=False, unit="in", note="report only"))
        rows.append(fpmv.row(PROBLEM, "energy balance error", 0.0, res["summary"]["energy_error"],
                             TOL_ENERGY if tested else None, mesh=mesh, wall=wall, plot=plot_name,
                             relative=False))
        rows.append(fpmv.row(PROBLEM, "peak equivalent plastic strain", 0.0,
                             res["summary"]["plastic_strain"]["max"], None, mesh=mesh, wall=wall,
                             plot=plot_name, relative=False,
                             note="%s surface; report only" % res["summary"]["plastic_strain"]["surface"]))
    draw(plot, curves)
    return fpmv.finish(args.out, rows)


def draw(path, curves):
    plt = fpmv.pyplot()
    fig, ax = plt.subplots(figsize=(8, 5))
    for name, (t, w) in sorted(curves.items()):
        ax.plot([x * 1e3 for x in t], w, "k:" if name.startswith("elastic ") else "-", lw=1.2,
                label="fpmshell " + name)
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("apex deflection $u_z$ [in]")
    ax.set_title("Spherical cap, step pressure 600 psi, elastic-plastic")
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())

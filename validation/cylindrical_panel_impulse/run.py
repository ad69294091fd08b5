#!/usr/bin/env python3
"""Impulsively loaded cylindrical panel (Balmer & Witmer; benchmarks.md 5.2).

Half model (model.yaml: crown symmetry line, the other three edges clamped, 5650 in/s inward
radial initial velocity under the explosive, +-30 deg x 0 <= y <= 10.21 in) on half-model meshes
8x32 ... 48x192 (arc x length). Peak inward crown deflection at y = 6.28 in against the band of
benchmarks.md 5.2; crown histories at y = 6.28 and 9.42 in and the crown profile at 1 ms
plotted. See README.md. Protocol: validation/README.md.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import fpmv  # noqa: E402

PROBLEM = "cylindrical_panel_impulse"
# Half-model divisions (arc over 60 deg, length over 12.56 in). Arc even and length a multiple
# of 16: the borders of the loaded region (phi = 30 deg, y = 10.205 in) are node lines and the
# crown points y = 6.28 and 9.42 in are nodes (model.yaml).
MESHES_FULL = [(8, 32), (16, 64), (24, 96), (32, 128), (48, 192)]   # the finest is tested
MESHES_QUICK = [(8, 32), (16, 64)]                                  # about 3 s together
END_TIME = 1.0e-3

# Data of benchmarks.md 5.2 (half model)
R, THICK, RHO, V0 = 2.938, 0.125, 2.5e-4, 5650.0
LOADED_AREA = R * math.radians(30.0) * 10.21          # half model: 30 deg x 10.21 in
KE_CONTINUUM = 0.5 * RHO * THICK * LOADED_AREA * V0**2  # 7834 in lbf, the half model's share

# ---- Tested. Each band is benchmarks.md 5.2's: "Band to meet: 1.15-1.30 in at 0.3-0.5 ms"
# (experiment 1.25 in at about 0.4 ms; converged shell computations 1.18-1.24 in). A tested row
# passes only inside its band; the tolerance written in rows.json is the band's half width over
# its centre, not a number fitted to fpmshell.
PEAK_W = (1.15, 1.30)   # in; tolerance: band of benchmarks.md 5.2 (finest mesh, and 16x64 quick)
PEAK_T = (0.30, 0.50)   # ms; tolerance: band of benchmarks.md 5.2 (every tested mesh)
# Quick variant, coarsest mesh 8x32 (the mesh of the coarse Abaqus S4R reference, 8x32 on the
# half model: 1.03 in, benchmarks.md 5.2): it passes from the coarse reference's 1.03 in up to
# the band's upper edge. Reason: an 8x32 half model cannot be asked to be inside the converged
# band (Abaqus's own 8x32 S4R is 0.12 in under it); it must do at least as well as the coarse published
# value. Measured here 1.092 in (9 % under the extrapolated limit of the study, 1.22 in).
COARSE_W = (1.03, 1.30)  # in; tolerance: coarse 8x32 S4R value of benchmarks.md 5.2 .. band top
# Mesh convergence: the peak changes by at most 2 % between the two finest meshes, i.e. the
# finest lies within about a third of the band's half width (6 %) of its limit: the band test
# tests the converged answer, not a mesh crossing the band on its way elsewhere.
TOL_CONVERGED = 0.02
TOL_ENERGY = 0.01        # energy balance error < 1 %, as every dynamic problem (benchmarks.md)

EXPERIMENT = (0.4, 1.25)  # (ms, in): maximum crown deflection at y = 6.28 in, "about 0.4 ms"
CONVERGED_SHELLS = (1.18, 1.24)   # published converged shell computations (drawn)


def peak(tm, w):
    """Largest inward deflection over the whole run: (value, time ms, on the last sample)."""
    i = max(range(len(w)), key=lambda k: w[k])
    v, t = fpmv.parabola_vertex(tm, w, i)
    return v, t, i == len(w) - 1


def crown_profile(out_dir):
    """(y, inward deflection) along the crown line x = 0 from the last field frame (1 ms);
    y is the reference coordinate (point - displacement)."""
    frames = sorted(f for f in os.listdir(os.path.join(out_dir, "fields")) if f.endswith(".vtu"))
    d = fpmv.read_vtu(os.path.join(out_dir, "fields", frames[-1]))
    prof = []
    for p, u in zip(d["points"], d["displacement"]):
        if abs(p[0] - u[0]) < 1e-6:
            prof.append((p[1] - u[1], -u[2]))
    return sorted(prof)


def band_row(quantity, band, value, mesh, wall, plot, tested, unit, note):
    """Reference = band centre, tolerance (relative) = half width over the centre; a tested row
    passes only inside [low, high] (tested exactly)."""
    centre = 0.5 * (band[0] + band[1])
    r = fpmv.row(PROBLEM, quantity, centre, value,
                 0.5 * (band[1] - band[0]) / abs(centre) if tested else None,
                 mesh=mesh, wall=wall, plot=plot, note=note + ("" if tested else "; report only"),
                 unit=unit)
    r["reference_text"] = "%g ... %g %s" % (band[0], band[1], unit)
    if tested:
        r["pass"] = band[0] - 1e-12 <= value <= band[1] + 1e-12
    return r


def main():
    args = fpmv.parse_args(__doc__)
    meshes = MESHES_QUICK if args.quick else MESHES_FULL
    model = os.path.join(HERE, "model.yaml")
    # the quick variant (make test) draws its own files so that it keeps the full ones
    suffix = "-quick" if args.quick else ""
    plot = fpmv.plot_path(PROBLEM + suffix + ".png")
    plot_prof = fpmv.plot_path(PROBLEM + "-profile" + suffix + ".png")
    plot_name, prof_name = os.path.basename(plot), os.path.basename(plot_prof)
    rows, runs, peaks = [], [], {}
    for na, nl in meshes:
        out = os.path.join(args.out, "half-%dx%d" % (na, nl))
        particles = (na + 1) * (nl + 1)
        res, wall = fpmv.run_or_reuse(args, model, out, ["mesh.divisions_arc=%d" % na,
                                                         "mesh.divisions_length=%d" % nl,
                                                         "control.end_time=%g" % END_TIME],
                                      END_TIME, particles)
        h, s, e = res["history"], res["summary"], res["energy"]
        tm = [x * 1e3 for x in h["time"]]
        w628 = [-x for x in h["w_628"]]
        w942 = [-x for x in h["w_942"]]
        label = "%dx%d" % (na, nl)
        mesh = "half %s, %d particles, dkt" % (label, s["particles"])
        runs.append((label, tm, w628, w942, crown_profile(out)))
        kw = dict(mesh=mesh, wall=wall, plot=plot_name)
        if h["time"][-1] < END_TIME * (1 - 1e-9):
            rows.append(fpmv.row(PROBLEM, "run reached 1 ms", 1.0, tm[-1], 0.0, relative=False,
                                 unit="ms", **kw))
            continue
        finest = (na, nl) == meshes[-1]
        coarse_quick = args.quick and (na, nl) == meshes[0]
        p = peak(tm, w628)
        peaks[(na, nl)] = p[0]
        src = ("band of benchmarks.md 5.2 (experiment 1.25 in at about 0.4 ms; converged "
               "shells 1.18-1.24 in)")
        if coarse_quick:
            rows.append(band_row("peak inward crown deflection at y = 6.28 in", COARSE_W, p[0],
                                 mesh, wall, plot_name, True, "in",
                                 "coarse mesh: from the coarse 8x32 S4R value 1.03 in of "
                                 "benchmarks.md 5.2 to the band's top 1.30 in"))
        else:
            rows.append(band_row("peak inward crown deflection at y = 6.28 in", PEAK_W, p[0],
                                 mesh, wall, plot_name, finest or args.quick, "in", src))
        r = band_row("time of the peak at y = 6.28 in", PEAK_T, p[1], mesh, wall, plot_name,
                     finest or args.quick, "ms", src)
        if p[2]:
            r["note"] += "; THE MAXIMUM IS THE LAST SAMPLE (still growing at 1 ms)"
            r["pass"] = r["tolerance"] is None
        rows.append(r)
        rows.append(fpmv.row(PROBLEM, "crown deflection at y = 6.28 in at 1 ms", p[0], w628[-1],
                             None, unit="in", note="reference: this mesh's peak; report only",
                             **kw))
        prof = runs[-1][4]
        ymax, wmax = max(prof, key=lambda p: p[1])
        r = fpmv.row(PROBLEM, "crown profile at 1 ms: largest inward deflection", 0.0, wmax, None,
                     relative=False, unit="in", mesh=mesh, wall=wall, plot=prof_name,
                     note="at y = %.2f in; no published value (benchmarks.md 5.2); report only"
                          % ymax)
        r["reference_text"] = "(plotted)"
        rows.append(r)
        q = peak(tm, w942)
        r = fpmv.row(PROBLEM, "peak inward crown deflection at y = 9.42 in", 0.0, q[0], None,
                     relative=False, unit="in",
                     note="at %.3f ms; no published value (benchmarks.md 5.2); report only"
                          % q[1], **kw)
        r["reference_text"] = "(plotted)"
        rows.append(r)
        r = fpmv.row(PROBLEM, "crown deflection at y = 9.42 in at 1 ms", 0.0, w942[-1], None,
                     relative=False, unit="in", note="report only", **kw)
        r["reference_text"] = "(plotted)"
        rows.append(r)
        rows.append(fpmv.row(PROBLEM, "energy balance error", 0.0, s["energy_error"],
                             TOL_ENERGY if (finest or args.quick) else None, relative=False,
                             note="< 1 %" if (finest or args.quick) else "report only",
                             **kw))
        rows.append(fpmv.row(PROBLEM, "initial kinetic energy (half model)", KE_CONTINUUM,
                             e["kinetic"][0], None, unit="in lbf",
                             note="reference: 1/2 rho h A v0^2 over the loaded 30 deg x 10.21 in; "
                                  "the mesh keeps the exact impulse (half velocity on the "
                                  "region's border nodes), so its energy is lower by O(h), and "
                                  "the clamped y = 0 nodes carry none; report only", **kw))
        rows.append(fpmv.row(PROBLEM, "plastic work at 1 ms / initial kinetic energy", 1.0,
                             e["plastic"][-1] / e["kinetic"][0], None, relative=False,
                             note="report only", **kw))
        rows.append(fpmv.row(PROBLEM, "peak equivalent plastic strain", 0.0,
                             s["plastic_strain"]["max"], None, relative=False,
                             note="%s surface; grows with refinement: a shear hinge at the "
                                  "clamped end y = 0 under the explosive (velocity jump at a "
                                  "clamped edge); report only" % s["plastic_strain"]["surface"],
                             **kw))
    # mesh convergence of the peak
    done = [m for m in meshes if m in peaks]
    if not args.quick and len(done) >= 2 and done[-1] == meshes[-1]:
        a, b = peaks[done[-2]], peaks[done[-1]]
        rows.append(fpmv.row(PROBLEM, "peak at y = 6.28 in: change between the two finest meshes",
                             b, a, TOL_CONVERGED,
                             mesh="%dx%d vs %dx%d" % (done[-2] + done[-1]), plot=plot_name,
                             unit="in",
                             note="|w(coarser) - w(finest)| / w(finest) <= 2 %: the finest is "
                                  "converged to a third of the band's half width (6 %)"))
    trip = None
    for m in sorted(done, reverse=True):   # the finest triple n, 2n, 4n (element size halved)
        m0, m1 = (m[0] // 4, m[1] // 4), (m[0] // 2, m[1] // 2)
        if m[0] % 4 == 0 and m[1] % 4 == 0 and m0 in peaks and m1 in peaks:
            trip = (m0, m1, m)
            break
    if trip:
        w1, w2, w3 = (peaks[m] for m in trip)
        order = fpmv.observed_order(w1, w2, w3)
        if not math.isnan(order):
            rows.append(fpmv.row(PROBLEM, "observed order of the peak at y = 6.28 in", 1.0,
                                 order, None, relative=False,
                                 mesh="%dx%d / %dx%d / %dx%d" % (trip[0] + trip[1] + trip[2]),
                                 plot=plot_name, note="log2((w1-w2)/(w2-w3)); report only"))
            extra = w3 + (w3 - w2) / (2**order - 1)
            r = fpmv.row(PROBLEM, "Richardson limit of the peak at y = 6.28 in",
                         0.5 * sum(PEAK_W), extra, None, unit="in", plot=plot_name,
                         mesh="from %dx%d / %dx%d / %dx%d" % (trip[0] + trip[1] + trip[2]),
                         note="report only")
            r["reference_text"] = "%g ... %g in" % PEAK_W
            rows.append(r)
    draw(plot, runs)
    draw_profile(plot_prof, runs)
    return fpmv.finish(args.out, rows)


def draw(path, runs):
    plt = fpmv.pyplot()
    fig, ax = plt.subplots(figsize=(8.5, 5.5))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    ax.fill_between([PEAK_T[0], PEAK_T[1]], PEAK_W[0], PEAK_W[1], color="0.85",
                    label="band of benchmarks.md 5.2 (1.15-1.30 in at 0.3-0.5 ms)")
    ax.fill_between([PEAK_T[0], PEAK_T[1]], CONVERGED_SHELLS[0], CONVERGED_SHELLS[1],
                    color="0.7", label="converged shell computations 1.18-1.24 in")
    for k, (label, tm, w628, w942, _) in enumerate(runs):
        c = colors[k % len(colors)]
        ax.plot(tm, w628, "-", color=c, lw=1.2, label="y = 6.28 in, half %s" % label)
        ax.plot(tm, w942, "--", color=c, lw=1.0, label="y = 9.42 in, half %s" % label)
    ax.plot([EXPERIMENT[0]], [EXPERIMENT[1]], "k*", ms=12,
            label="experiment: max at y = 6.28 in, 1.25 in at ~0.4 ms")
    ax.set_xlim(0, 1.0)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("inward crown deflection $-u_z$ [in]")
    ax.legend(fontsize=7, loc="lower right", ncol=2)
    ax.grid(alpha=0.3)
    fpmv.save_figure(fig, path,
                     "Impulsively loaded cylindrical panel (Balmer & Witmer), crown histories")


def draw_profile(path, runs):
    plt = fpmv.pyplot()
    fig, ax = plt.subplots(figsize=(8.5, 4.5))
    for label, _, _, _, prof in runs:
        ax.plot([p[0] for p in prof], [p[1] for p in prof], "-", lw=1.2, label="half " + label)
    ax.axvspan(0, 10.21, color="0.92", label="under the explosive (y <= 10.21 in)")
    for y in (6.28, 9.42):
        ax.axvline(y, color="k", lw=0.6, ls=":")
    ax.set_xlim(0, 12.56)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("y along the crown [in]")
    ax.set_ylabel("inward crown deflection at 1 ms [in]")
    ax.legend(fontsize=8, loc="upper right")
    ax.grid(alpha=0.3)
    fpmv.save_figure(fig, path,
                     "Cylindrical panel: crown profile at 1 ms (no published values to compare)")


if __name__ == "__main__":
    sys.exit(main())

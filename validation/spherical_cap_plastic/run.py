#!/usr/bin/env python3
"""Shallow spherical cap under a suddenly applied pressure, elastic-plastic (benchmarks.md 5.1).

Full cap (model.yaml: sigma_y = 24 000 psi, E_t = 0.21e6 psi, bilinear isotropic) with 127, 469,
631, 1261, 2437 and 4921 particles (the paper's models I-III and three finer ones), plus the
elastic cap on the finest mesh for comparison; apex deflection history against the bands and
the reference points of benchmarks.md 5.1, read from the Abaqus/Explicit curve of the Abaqus
Benchmarks Guide 2.3.14. See README.md. Protocol: validation/README.md.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import fpmv  # noqa: E402

PROBLEM = "spherical_cap_plastic"
PARTICLES = {6: 127, 12: 469, 14: 631, 20: 1261, 28: 2437, 40: 4921}
RINGS_FULL = [6, 12, 14, 20, 28, 40]   # the finest (40 rings) is tested, the others reported
RINGS_QUICK = [12]                     # the paper's model II, tested against the same bands
END_TIME = 1.0e-3   # both variants: the "no positive excursion before 1 ms" row needs 1 ms

# ---- Tested: the BANDS of benchmarks.md 5.1, read from the figure of the Abaqus Benchmarks
# Guide 2.3.14 (Abaqus/Explicit S4R/S4RS/SAX1 curve). (low, high), in and ms. A tested row passes
# only inside its band; the tolerance is the band's half width (the reading and the spread the
# band allows), not a number fitted to fpmshell.
PEAK_W = (-0.072, -0.060)      # tolerance: band of benchmarks.md 5.1, Abaqus BG 2.3.14 fig.
PEAK_T = (0.43, 0.52)          # tolerance: band of benchmarks.md 5.1, Abaqus BG 2.3.14 fig.
REBOUND_W = (-0.028, -0.010)   # tolerance: band of benchmarks.md 5.1, Abaqus BG 2.3.14 fig.
REBOUND_T = (0.62, 0.70)       # tolerance: band of benchmarks.md 5.1, Abaqus BG 2.3.14 fig.
NO_POSITIVE_UNTIL = 1.0        # ms; band of benchmarks.md 5.1 (Abaqus BG 2.3.14): max apex w < 0
TOL_ENERGY = 0.01              # energy balance error < 1 %, as every dynamic problem (benchmarks.md)

# ---- Reported: the reference POINTS read from the same figure (benchmarks.md 5.1).
PLATEAU_W = (-0.061, -0.057)   # first plateau, in ...
PLATEAU_T = (0.18, 0.27)       # ... over this time span, ms
PEAK_POINT = (-0.066, 0.47)    # first major peak (in, ms "about")
REBOUND_POINT = (-0.019, 0.65)  # rebound (in, ms "about")
SECOND_W = -0.070              # second peak "near -0.070 in" ...
SECOND_T = (0.85, 0.90)        # ... at 0.85-0.90 ms
SET_W = -0.045                 # the oscillation is centred on a permanent set of "about -0.045 in"

# ---- How the features are picked from the apex history (ms). The windows come from the
# reference figure, not from fpmshell's curves:
PLATEAU_END = 0.30       # the plateau: up to 0.30 ms (the reference's plateau ends at 0.27 ms)
PEAK_WINDOW = (0.30, 0.60)  # first major peak: the minimum over 0.30-0.60 ms, i.e. after the
#                          reference's plateau (<= 0.27) and before its rebound (>= 0.62); the
#                          peak band 0.43-0.52 lies inside with >= 0.08 ms either side.
REBOUND_END = 0.80       # rebound: the maximum from the first major peak to 0.80 ms, midway
#                          between the reference's rebound (<= 0.70) and second peak (>= 0.85)
# Second peak: the minimum from the rebound to the end (1 ms); also the minimum over the
# reference's own span 0.85-0.90 ms (the second trough can hold two dips of nearly equal depth).
# An extremum that falls on the edge of its window is not a trough/crest of the curve: its rows
# say so and tested ones fail.
# Permanent set: the centre of the oscillation, (rebound + second peak) / 2, which is what "the
# oscillation centred on" reads from a figure; also the time mean from 0.6 ms to 1 ms (the
# earlier definition of this script, kept for comparison).
SET_MEAN_FROM = 0.6


def extremum(tm, w, idx, kind):
    """(value, time, on_edge) of the min or max of w over the sample indices idx (ascending);
    refined by the parabola unless it lies on the first or last sample of idx."""
    if not idx:
        return None
    i = (min if kind == "min" else max)(idx, key=lambda k: w[k])
    edge = i == idx[0] or i == idx[-1]
    v, t = (w[i], tm[i]) if edge else fpmv.parabola_vertex(tm, w, i)
    return v, t, edge


def interp(tm, w, x):
    for k in range(len(tm) - 1):
        if tm[k] <= x <= tm[k + 1]:
            s = (x - tm[k]) / (tm[k + 1] - tm[k]) if tm[k + 1] > tm[k] else 0.0
            return w[k] + s * (w[k + 1] - w[k])
    return w[-1]


def time_mean(tm, w, a, b):
    """Mean of w over [a, b] (trapezoids, w linear between samples)."""
    pts = [(a, interp(tm, w, a))] + [(x, y) for x, y in zip(tm, w) if a < x < b] + \
          [(b, interp(tm, w, b))]
    area = sum(0.5 * (pts[k][1] + pts[k + 1][1]) * (pts[k + 1][0] - pts[k][0])
               for k in range(len(pts) - 1))
    return area / (b - a)


def features(t, w):
    """The features of an apex history (times in ms); a key is absent when the run is too short
    for it."""
    tm = [x * 1e3 for x in t]
    end = tm[-1]
    f = {}
    def span(lo, hi, lo_open=False):
        return [k for k, x in enumerate(tm) if (x > lo if lo_open else x >= lo) and x <= hi]

    f["plateau_min"] = extremum(tm, w, span(0, PLATEAU_END, lo_open=True), "min")
    if end >= PLATEAU_T[1]:
        f["plateau_mean"] = time_mean(tm, w, PLATEAU_T[0], PLATEAU_T[1])
    if end < PEAK_WINDOW[1]:
        return f
    f["peak"] = extremum(tm, w, span(*PEAK_WINDOW), "min")
    # cross-check with the other natural definition: the first local minimum after the plateau
    # that is deeper than the plateau; a note when the two differ
    pv, pt = f["plateau_min"][0], f["plateau_min"][1]
    alt = next((k for k in range(1, len(w) - 1) if tm[k] > pt and w[k] <= w[k - 1]
                and w[k] <= w[k + 1] and w[k] < pv), None)
    f["peak_alt"] = None if alt is None else (w[alt], tm[alt])
    if end >= REBOUND_END:
        tp = f["peak"][1]
        f["rebound"] = extremum(tm, w, span(tp, REBOUND_END, lo_open=True), "max")
    until = NO_POSITIVE_UNTIL * (1 + 1e-9)
    if end >= NO_POSITIVE_UNTIL * (1 - 1e-9):
        f["max_w"] = max(w[k] for k in span(0, until, lo_open=True))
        f["max_w_late"] = max(w[k] for k in span(0.1, until))
        f["second"] = extremum(tm, w, span(f["rebound"][1], until, lo_open=True), "min")
        f["second_in_span"] = extremum(tm, w, span(*SECOND_T), "min")
        f["set_centre"] = 0.5 * (f["rebound"][0] + f["second"][0])
        f["set_mean"] = time_mean(tm, w, SET_MEAN_FROM, NO_POSITIVE_UNTIL)
    return f


def band_row(quantity, band, feat, mesh, wall, plot, tested, unit):
    """A band row: reference = band centre, tolerance (relative) = half width over |centre|;
    a tested row passes only inside [low, high] (tested exactly) and off its window's edge."""
    value, _, edge = feat if isinstance(feat, tuple) else (feat, None, False)
    centre = 0.5 * (band[0] + band[1])
    note = ("band of benchmarks.md 5.1 read from the Abaqus Benchmarks Guide 2.3.14 figure: "
            "%g ... %g %s" % (band[0], band[1], unit))
    if edge:
        note += "; ON THE EDGE OF ITS WINDOW (no interior extremum)"
    r = fpmv.row(PROBLEM, quantity, centre, value,
                 0.5 * (band[1] - band[0]) / abs(centre) if tested else None, mesh=mesh,
                 wall=wall, plot=plot, note=note, unit=unit)
    r["reference_text"] = "%g ... %g %s" % (band[0], band[1], unit)
    if tested:
        r["pass"] = band[0] - 1e-12 <= value <= band[1] + 1e-12 and not edge
    return r


def point_row(quantity, ref, value, mesh, wall, plot, unit, rng=None, relative=False,
              note="", edge=False):
    """A report-only row against a reference point read from the figure; rng: its read range."""
    text = "%g %s" % (ref, unit)
    if rng:
        inside = rng[0] <= value <= rng[1]
        text = "%g ... %g %s" % (rng[0], rng[1], unit)
        note = ("inside" if inside else "outside") + " the read range" + (
            "; " + note if note else "")
    if edge:
        note += "; on the edge of its window"
    r = fpmv.row(PROBLEM, quantity, ref, value, None, mesh=mesh, wall=wall, plot=plot,
                 relative=relative, unit=unit,
                 note="reference point of benchmarks.md 5.1 (Abaqus BG 2.3.14 figure)" +
                 ("; " + note if note else "") + "; report only")
    r["reference_text"] = text
    return r


def main():
    args, rings, plot, plot_name = fpmv.start(PROBLEM, __doc__, RINGS_QUICK, RINGS_FULL)
    model = os.path.join(HERE, "model.yaml")
    elastic_model = os.path.join(HERE, "..", "spherical_cap_elastic", "model.yaml")
    rows, curves = [], []
    finest = rings[-1]
    ov_end = ["control.end_time=%g" % END_TIME]
    el, _ = fpmv.run_or_reuse(args, elastic_model, os.path.join(args.out, "elastic-%d" % finest),
                              ["mesh.divisions=%d" % finest] + ov_end, END_TIME, PARTICLES[finest])
    elastic = ("elastic, %d rings (%d particles)" % (finest, PARTICLES[finest]),
               el["history"]["time"], el["history"]["apex_w"])
    for n in rings:
        res, wall = fpmv.run_or_reuse(args, model, os.path.join(args.out, "plastic-%d" % n),
                                      ["mesh.divisions=%d" % n] + ov_end, END_TIME, PARTICLES[n])
        t, w = res["history"]["time"], res["history"]["apex_w"]
        curves.append(("elastic-plastic, %d rings (%d particles)" % (n, PARTICLES[n]), t, w))
        f = features(t, w)
        mesh = "%d rings, %d particles, bciz" % (n, PARTICLES[n])
        tested = n == finest
        kw = dict(mesh=mesh, wall=wall, plot=plot_name)
        if "peak" not in f or "max_w" not in f:
            rows.append(fpmv.row(PROBLEM, "run reached 1 ms", END_TIME * 1e3, t[-1] * 1e3, 0.0,
                                 relative=False, unit="ms", **kw))
            continue
        # tested on the finest mesh (bands), reported on the others
        r = band_row("first major peak apex w (min over %g-%g ms)" % PEAK_WINDOW, PEAK_W,
                     f["peak"], mesh, wall, plot_name, tested, "in")
        if f["peak_alt"] and abs(f["peak_alt"][1] - f["peak"][1]) > 0.01:
            r["note"] += ("; the first local minimum after the plateau deeper than it is %.4g in "
                          "at %.3f ms" % f["peak_alt"])
        rows.append(r)
        rows.append(band_row("first major peak time", PEAK_T, (f["peak"][1], 0, f["peak"][2]),
                             mesh, wall, plot_name, tested, "ms"))
        rows.append(band_row("rebound maximum apex w (max from the first major peak to %g ms)"
                             % REBOUND_END, REBOUND_W, f["rebound"], mesh, wall, plot_name,
                             tested, "in"))
        rows.append(band_row("rebound time", REBOUND_T, (f["rebound"][1], 0, f["rebound"][2]),
                             mesh, wall, plot_name, tested, "ms"))
        r = fpmv.row(PROBLEM, "no positive excursion: max apex w over 0 < t <= 1 ms", 0.0,
                     f["max_w"], None, relative=False, unit="in",
                     note="band of benchmarks.md 5.1 read from the Abaqus Benchmarks Guide 2.3.14 "
                          "figure: passes when < 0 (the elastic cap rebounds to about +0.043 in); "
                          "the largest value from 0.1 ms on is %.4g in" % f["max_w_late"], **kw)
        r["reference_text"] = "< 0 in"
        if tested:
            r["tolerance"] = 0.0
            r["pass"] = f["max_w"] < 0
        rows.append(r)
        rows.append(fpmv.row(PROBLEM, "energy balance error", 0.0, res["summary"]["energy_error"],
                             TOL_ENERGY if tested else None, relative=False,
                             note="< 1 %" if tested else "report only", **kw))
        # reported against the reference points of the figure
        rows.append(point_row("plateau: mean apex w over %g-%g ms" % PLATEAU_T,
                              0.5 * (PLATEAU_W[0] + PLATEAU_W[1]), f["plateau_mean"], mesh, wall,
                              plot_name, "in", rng=PLATEAU_W))
        rows.append(point_row("plateau: deepest apex w up to %g ms" % PLATEAU_END,
                              0.5 * (PLATEAU_W[0] + PLATEAU_W[1]), f["plateau_min"][0], mesh,
                              wall, plot_name, "in", rng=PLATEAU_W, edge=f["plateau_min"][2]))
        rows.append(point_row("plateau: time of the deepest point",
                              0.5 * (PLATEAU_T[0] + PLATEAU_T[1]), f["plateau_min"][1], mesh,
                              wall, plot_name, "ms", rng=PLATEAU_T, edge=f["plateau_min"][2]))
        rows.append(point_row("second peak apex w (min from the rebound to 1 ms)", SECOND_W,
                              f["second"][0], mesh, wall, plot_name, "in", relative=True,
                              edge=f["second"][2]))
        rows.append(point_row("second peak time", 0.5 * (SECOND_T[0] + SECOND_T[1]),
                              f["second"][1], mesh, wall, plot_name, "ms", rng=SECOND_T,
                              edge=f["second"][2]))
        rows.append(point_row("second peak: deepest apex w over %g-%g ms" % SECOND_T, SECOND_W,
                              f["second_in_span"][0], mesh, wall, plot_name, "in", relative=True,
                              edge=f["second_in_span"][2]))
        rows.append(point_row("permanent set: centre of the oscillation, (rebound + second "
                              "peak) / 2", SET_W, f["set_centre"], mesh, wall, plot_name, "in",
                              relative=True))
        rows.append(point_row("permanent set: mean apex w over %g-%g ms" % (SET_MEAN_FROM,
                                                                         NO_POSITIVE_UNTIL),
                              SET_W, f["set_mean"], mesh, wall, plot_name, "in", relative=True))
        rows.append(fpmv.row(PROBLEM, "peak equivalent plastic strain", 0.0,
                             res["summary"]["plastic_strain"]["max"], None, relative=False,
                             note="%s surface; report only"
                                  % res["summary"]["plastic_strain"]["surface"], **kw))
    draw(plot, curves, elastic)
    return fpmv.finish(args.out, rows)


def draw(path, curves, elastic):
    plt = fpmv.pyplot()
    from matplotlib.patches import Rectangle
    fig, ax = plt.subplots(figsize=(9, 7))
    for k, ((lo_t, hi_t), (lo_w, hi_w)) in enumerate(((PEAK_T, PEAK_W), (REBOUND_T, REBOUND_W))):
        ax.add_patch(Rectangle((lo_t, lo_w), hi_t - lo_t, hi_w - lo_w, color="0.8", alpha=0.7,
                               zorder=0, label="bands (tested): Abaqus BG 2.3.14, benchmarks.md 5.1"
                               if k == 0 else None))
    ax.plot([0, NO_POSITIVE_UNTIL], [0, 0], color="r", lw=1.5, zorder=1,
            label="band (tested): no positive excursion before 1 ms")
    cmap = plt.get_cmap("viridis")
    for k, (name, t, w) in enumerate(curves):
        ax.plot([x * 1e3 for x in t], w, "-", lw=1.6 if k == len(curves) - 1 else 1.0,
                color=cmap(k / max(1, len(curves) - 1) * 0.9), label="fpmshell " + name, zorder=2)
    ax.plot([x * 1e3 for x in elastic[1]], elastic[2], "k:", lw=1.0, label="fpmshell " + elastic[0],
            zorder=2)
    # reference points read from the figure: the plateau as the box of its read ranges, the
    # second peak with its read time span, the two "about" points as markers
    ax.add_patch(Rectangle((PLATEAU_T[0], PLATEAU_W[0]), PLATEAU_T[1] - PLATEAU_T[0],
                           PLATEAU_W[1] - PLATEAU_W[0], fill=False, ec="crimson", lw=1.2, zorder=3,
                           label="reference plateau (Abaqus BG 2.3.14 figure): read ranges"))
    ax.plot([PEAK_POINT[1], REBOUND_POINT[1]], [PEAK_POINT[0], REBOUND_POINT[0]], "s",
            color="crimson", mfc="none", ms=7, zorder=3,
            label="reference first major peak and rebound (figure)")
    ax.errorbar([0.5 * (SECOND_T[0] + SECOND_T[1])], [SECOND_W],
                xerr=[0.5 * (SECOND_T[1] - SECOND_T[0])], fmt="D", color="crimson", mfc="none",
                ms=6, capsize=3, zorder=3, label="reference second peak (figure): read time span")
    ax.plot([0.45, 1.0], [SET_W, SET_W], "--", color="crimson", lw=1.0, zorder=3,
            label="reference permanent set, about %g in" % SET_W)
    ax.set_xlim(0, 1.0)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("apex deflection $u_z$ [in]")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=2)
    ax.set_ylim(-0.1, 0.05)
    ax.grid(alpha=0.3)
    fpmv.save_figure(fig, path, "Spherical cap, step pressure 600 psi, elastic-plastic "
                     "(σ_y 24 000 psi, E_t 0.21e6 psi)")


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Thin-walled square tube struck axially by a heavy rigid mass (benchmarks.md 5.3).

Quarter model of examples/square_tube/model.yaml (steel 100 x 100 x 3 mm, 400 mm long,
Johnson-Cook with mixed hardening, 800 kg at 9.5 m/s, self-contact and a rigid striker).
Checks against theory: the mean crushing force of Abramowicz & Jones with the rate factor of
the model's own Johnson-Cook law, the fold length 2H, the energy balance, and the largest
contact penetration. Reports the force and end-acceleration histories, deformed shapes, fold
count, final crush and peak plastic strains. See README.md. Protocol: validation/README.md.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import fpmv  # noqa: E402

PROBLEM = "square_tube"
MODEL = os.path.join(HERE, "..", "..", "examples", "square_tube", "model.yaml")
# (divisions across each modelled face, divisions along the tube); the paper's mesh is (30, 128)
MESHES_FULL = [(15, 64), (20, 86), (30, 128)]
MESH_QUICK = (8, 32)
THREADS = {(20, 86): 2, (30, 128): 2}  # the finer meshes run on two threads, the coarse on one
END_QUICK = 3.0e-3     # the first fold forms (a few force peaks)
# The full runs end when the block stops (control.end_when_body_stops of the example): after
# 55-60 ms depending on the mesh (56.6 ms on 15 x 64, 58.5 on 20 x 86, 59.9 on the paper's
# 30 x 128); END_FULL is only the upper bound.
END_FULL = 0.08

# Geometry and material of the model (SI)
B, T, L = 0.1, 0.003, 0.4
M_QUARTER, V0 = 200.0, 9.5
JC_A, JC_B, JC_N, JC_C, EPS0 = 350e6, 275e6, 0.36, 0.022, 1.0

# Tolerances (docs/benchmarks.md §5.3): the mean crushing force within 25 % of Abramowicz-Jones (the formula
# itself scatters by about that much against tests), the fold length within 25 % of 2H, the
# energy balance within 2 %, and no particle inside a contact surface by 10 % of the wall.
TOL_FORCE = 0.25
TOL_FOLD = 0.25
TOL_ENERGY = 0.02
TOL_PENETRATION = 0.10
TOL_CONTACT_ENERGY = 0.005
# Quick variant (make test): regression values of this version on the coarse tube at 3 ms,
# within 3 % (a change of the element, the material or the contact that moves them further
# must be explained); the energy balance within 0.5 %.
# (Re-measured when the example got its mode trigger: before it, -8.47357 m/s and 525.357 kN.)
QUICK_REFERENCE = {"striker velocity at 3 ms [m/s]": -8.79047, "largest striker force [kN]": 508.336}
TOL_QUICK = 0.03
TOL_ENERGY_QUICK = 0.005


def ultimate_tensile_strength():
    """Engineering ultimate tensile strength of the Johnson-Cook law at the reference rate: the
    true stress at the Considere strain (d sigma / d eps = sigma) times exp(-eps)."""
    lo, hi = 1e-6, 2.0
    for _ in range(200):  # bisection on B n e^(n-1) - (A + B e^n), positive below the root
        mid = 0.5 * (lo + hi)
        if JC_B * JC_N * mid ** (JC_N - 1) > JC_A + JC_B * mid ** JC_N:
            lo = mid
        else:
            hi = mid
    return (JC_A + JC_B * lo ** JC_N) * math.exp(-lo)


def flow_stress_tensile():
    """sigma0 of the theory: the flow stress of the rigid-perfectly plastic material that stands
    for a hardening one, by the common crashworthiness convention (sigma_y + sigma_u) / 2 from
    the tensile test (engineering stresses, like the test data the formula was fitted to)."""
    return 0.5 * (JC_A + ultimate_tensile_strength())


def flow_stress_mean(eps_max):
    """Energy-equivalent Johnson-Cook flow stress: the mean of A + B eps^n over 0..eps_max."""
    return JC_A + JC_B * eps_max ** JC_N / (1 + JC_N)


def abramowicz_jones(sigma0, factor):
    """Mean crushing force of a square tube (Abramowicz & Jones 1984), full tube [N]."""
    return 13.06 * sigma0 * T ** (5.0 / 3.0) * B ** (1.0 / 3.0) * factor


def fold_length_theory():
    """2H = 2 x 0.99 t^(1/3) b^(2/3) (Abramowicz & Jones)."""
    return 2 * 0.99 * T ** (1.0 / 3.0) * B ** (2.0 / 3.0)


def strain_rate():
    """Mean strain rate of the folding hinges, 0.33 v0 / b (benchmarks.md 5.3)."""
    return 0.33 * V0 / B


def crush_summary(hist):
    """Final crush, stop time and mean force from the striker history (quarter -> full)."""
    t, u, v, f = hist["time"], hist["striker_uz"], hist["striker_vz"], hist["striker_force"]
    stop = next((i for i in range(len(v)) if v[i] >= 0), len(v) - 1)
    crush = -u[stop]
    ke_lost = 0.5 * M_QUARTER * (V0 ** 2 - v[stop] ** 2)
    return {"stop_time": t[stop], "crush": crush, "stopped": v[stop] >= 0,
            "mean_force": 4 * ke_lost / crush if crush > 0 else 0.0,
            "peak_force": 4 * max(f), "final_velocity": v[-1]}


def wall_lobes(line):
    """Lobes of one wall middle line [(z0, w)] sorted by z0: runs of one sign with |w| above 30 %
    of the largest (the crushed lobes stand out by 20-30 mm; the gentle bulge of the uncrushed
    part is left out), each as [sign, z0 of its extreme, |w| there], the ends excluded."""
    threshold = 0.3 * max(abs(w) for _, w in line)
    lobes, current = [], None
    for z0, w in line:
        s = 1 if w > threshold else -1 if w < -threshold else 0
        if s == 0:
            current = None
            continue
        if current is None or current[0] != s:
            current = [s, z0, abs(w)]
            lobes.append(current)
        elif abs(w) > current[2]:
            current[1], current[2] = z0, abs(w)
    # A lobe whose extreme is an end of the tube is the end itself turned out or in (the top
    # edge slides on the block), a fold cut short whose middle is not known: left out.
    ends = (line[0][0], line[-1][0])
    return [lobe for lobe in lobes if lobe[1] not in ends]


def half_spacings(lobes):
    """Half the spacings of successive lobes of the same sign along a wall."""
    spacing = []
    for sign in (1, -1):
        z = [lz for s, lz, _ in lobes if s == sign]
        spacing += [0.5 * abs(z[i + 1] - z[i]) for i in range(len(z) - 1)]
    return spacing


def fold_analysis(frame_path):
    """Folds along the middle lines of the two modelled walls in the last frame: the wall x = b/2
    on the symmetry plane y = 0 and the wall y = b/2 on x = 0, lateral deflection w(z0) against
    the initial height z0. Each lobe is one fold of Abramowicz and Jones' mechanism: two plates
    of length H turned about a hinge at mid-lobe, so it consumes 2H of the original length and
    stands out by about H; lobes alternate outwards and inwards along a wall, so 2H is half the
    spacing of successive lobes of the same sign. Both walls count: the tube need not fold in
    the symmetric mode (one wall out where the next is in); in the mixed modes the two walls
    have lobes of different lengths, and one wall alone would give a biased 2H."""
    f = fpmv.read_vtu(frame_path)
    pts, disp = f["points"], f["displacement"]
    lines = {"x": [], "y": []}
    for p, d in zip(pts, disp):
        x0 = [p[k] - d[k] for k in range(3)]
        if abs(x0[1]) < 1e-9 and abs(x0[0] - B / 2) < 1e-9:
            lines["x"].append((x0[2], p[0] - B / 2))
        if abs(x0[0]) < 1e-9 and abs(x0[1] - B / 2) < 1e-9:
            lines["y"].append((x0[2], p[1] - B / 2))
    walls = {}
    for wall, line in lines.items():
        line.sort()
        lobes = wall_lobes(line)
        sp = half_spacings(lobes)
        walls[wall] = {"lobes": lobes, "spacings": sp, "line": line,
                       "fold_length": sum(sp) / len(sp) if sp else float("nan")}
    pooled = walls["x"]["spacings"] + walls["y"]["spacings"]
    all_lobes = walls["x"]["lobes"] + walls["y"]["lobes"]
    # Mode: at the height of each lobe of wall x, does wall y bulge the same way? Abramowicz and
    # Jones' symmetric mode alternates (one wall out where the next is in, the corners fold
    # without stretching); with the walls in phase (all out together) the corners stretch round
    # the tube, the extensional mode, whose folds are not those of the 2H formula.
    in_phase = 0
    y_line = walls["y"]["line"]
    for sign, z0, _ in walls["x"]["lobes"]:
        w_y = min(y_line, key=lambda q: abs(q[0] - z0))[1]
        in_phase += 1 if sign * w_y > 0 else 0
    n_x = len(walls["x"]["lobes"])
    return {"folds": max(len(w["lobes"]) for w in walls.values()),
            "depth": max(a for _, _, a in all_lobes) if all_lobes else 0.0,
            "fold_length": sum(pooled) / len(pooled) if pooled else float("nan"),
            "in_phase": in_phase, "lobes_x": n_x,
            "mode": "walls in phase (extensional)" if 2 * in_phase > n_x else "walls alternate (symmetric)",
            "walls": walls}


def frames_by_time(out_dir):
    """(time, path) of the VTU frames of a run that are on disk, from fields.pvd."""
    import re
    text = open(os.path.join(out_dir, "fields.pvd")).read()
    frames = [(float(t), os.path.join(out_dir, f))
              for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]
    return [f for f in frames if os.path.isfile(f[1])]


def has_frames_at(out_dir, times, within=0.3e-3):
    """Whether the run in out_dir has a frame within `within` of each of these times."""
    frames = frames_by_time(out_dir)
    return all(any(abs(t - want) <= within for t, _ in frames) for want in times)


def main():
    def mesh_option(ap):
        ap.add_argument("--meshes", help="the full study on these meshes only, e.g. 15x64,20x86 "
                        "(default: all of MESHES_FULL; the finest is the tested one)")

    args = fpmv.parse_args(__doc__, mesh_option)
    meshes = [MESH_QUICK] if args.quick else MESHES_FULL
    if args.meshes and not args.quick:
        meshes = [tuple(int(n) for n in m.split("x")) for m in args.meshes.split(",")]
    suffix = "-quick" if args.quick else ""
    plot = fpmv.plot_path(PROBLEM + suffix + ".png")
    shapes = fpmv.plot_path(PROBLEM + suffix + "-shapes.png")
    plot_name = os.path.basename(plot)
    rows, runs = [], {}
    jc_factor = 1 + JC_C * math.log(strain_rate() / EPS0)
    p_aj_jc = abramowicz_jones(flow_stress_tensile(), jc_factor)
    # The same formula with other flow stresses, for the record (see README.md "Flow stress").
    p_aj_yield = abramowicz_jones(JC_A, jc_factor)
    p_aj_mean = abramowicz_jones(flow_stress_mean(0.3), jc_factor)
    p_aj_cs = abramowicz_jones(JC_A, 1 + (strain_rate() / 40.4) ** (1 / 5.0))
    two_h = fold_length_theory()
    # The meshes run side by side within a budget of as many threads as the machine has cores,
    # the finest (longest) first, each on up to THREADS of them: more OpenMP threads than cores
    # make every thread wait at each barrier for one that is not running (the 30 x 128 run
    # slowed about 5 x so). On the 2-core CI machine the finest takes both cores and the coarse
    # ones follow it. The thread count does not change the results (bitwise).
    from concurrent.futures import ThreadPoolExecutor
    import threading
    end = END_QUICK if args.quick else END_FULL
    free = [os.cpu_count() or 1]
    budget = threading.Condition()

    def out_dir_of(mesh):
        return os.path.join(args.out, "%dx%d" % mesh)

    def run_mesh(mesh, threads):
        nw, nl = mesh
        over = ["mesh.divisions_width=%d" % nw, "mesh.divisions_length=%d" % nl, "control.end_time=%g" % end]
        try:
            return fpmv.run(args.fpmshell, MODEL, out_dir_of(mesh), over, threads=threads)
        finally:
            with budget:
                free[0] += threads
                budget.notify_all()

    results = [None] * len(meshes)
    futures = {}
    with ThreadPoolExecutor(max_workers=len(meshes)) as pool:
        for k in sorted(range(len(meshes)), key=lambda k: -meshes[k][0] * meshes[k][1]):
            nw, nl = meshes[k]
            # quarter model: 2 nw + 1 particles around, nl + 1 along; 4 nw nl triangles
            if args.reuse:
                results[k] = fpmv.reusable(out_dir_of(meshes[k]), end, (2 * nw + 1) * (nl + 1), 4 * nw * nl)
                if results[k]:
                    continue
            with budget:
                budget.wait_for(lambda: free[0] >= 1)
                threads = min(THREADS.get(meshes[k], 1), free[0])
                free[0] -= threads
            futures[k] = pool.submit(run_mesh, meshes[k], threads)
        for k, f in futures.items():
            results[k] = f.result()
    for (nw, nl), (res, wall) in zip(meshes, results):
        name = "%dx%d" % (nw, nl)
        runs[name] = res
        s, h, e = res["summary"], res["history"], res["energy"]
        tested = (nw, nl) == meshes[-1]
        mesh = "%s (%d particles, %d elements)" % (name, s["particles"], s["elements"])
        common = dict(mesh=mesh, wall=wall, plot=plot_name)
        c = s["contact"]
        rows.append(fpmv.row(PROBLEM, "largest contact penetration / wall thickness", 0.0,
                             c["max_penetration_ratio"], TOL_PENETRATION if tested else None,
                             relative=False, note="step %d, particle %d" % (
                                 c["max_penetration_step"], c["max_penetration_particle"]), **common))
        rows.append(fpmv.row(PROBLEM, "energy balance error", 0.0, s["energy_error"],
                             (TOL_ENERGY_QUICK if args.quick else TOL_ENERGY) if tested else None,
                             relative=False, **common))
        # Contact may dissipate energy (each impact is perfectly plastic) but must not create it:
        # a pair pushed out of a penetration against its force would (0.5 % allowed: the gaps
        # are linearised at the predictor).
        ke0 = e["external_work"][0]
        r = fpmv.row(PROBLEM, "contact energy / impact energy (must not be negative)", 0.0,
                     e["contact"][-1] / ke0, TOL_CONTACT_ENERGY if tested else None, relative=False,
                     note="%d pairs held inside" % c["held_penetrations"], **common)
        if tested:
            r["pass"] = r["value"] >= -TOL_CONTACT_ENERGY
        rows.append(r)
        rows.append(fpmv.row(PROBLEM, "contact share of the time loop", 0.0, c["share_of_time_loop"],
                             None, relative=False, note="%.1f s of %.1f s; report only" % (
                                 c["seconds"], s["wall_seconds"]), **common))
        cs = crush_summary(h)
        if args.quick:
            got = {"striker velocity at 3 ms [m/s]": h["striker_vz"][-1],
                   "largest striker force [kN]": cs["peak_force"] / 1e3}
            for q, ref in QUICK_REFERENCE.items():
                rows.append(fpmv.row(PROBLEM, "regression: " + q, ref if ref else got[q], got[q],
                                     TOL_QUICK if ref else None, **common))
            continue
        rows.append(fpmv.row(PROBLEM, "mean crushing force (full tube) vs Abramowicz-Jones, JC rate",
                             p_aj_jc / 1e3, cs["mean_force"] / 1e3, TOL_FORCE if tested else None,
                             unit="kN", note="energy of the block / final crush; sigma0 = (sigma_y + "
                             "sigma_u) / 2 = %.0f MPa (sigma_u = %.0f MPa, engineering), factor 1 + C "
                             "ln(0.33 v0/b) = %.3f" % (flow_stress_tensile() / 1e6,
                                                       ultimate_tensile_strength() / 1e6, jc_factor),
                             **common))
        rows.append(fpmv.row(PROBLEM, "mean crushing force vs Abramowicz-Jones, sigma0 = yield stress A",
                             p_aj_yield / 1e3, cs["mean_force"] / 1e3, None, unit="kN",
                             note="JC rate factor; report only", **common))
        rows.append(fpmv.row(PROBLEM, "mean crushing force vs Abramowicz-Jones, sigma0 = mean true flow "
                             "stress to eps 0.3", p_aj_mean / 1e3, cs["mean_force"] / 1e3, None, unit="kN",
                             note="%.0f MPa, JC rate factor (the reference of earlier versions); report only"
                             % (flow_stress_mean(0.3) / 1e6), **common))
        rows.append(fpmv.row(PROBLEM, "mean crushing force vs Abramowicz-Jones, Cowper-Symonds",
                             p_aj_cs / 1e3, cs["mean_force"] / 1e3, None, unit="kN",
                             note="sigma0 = A, mild steel D = 40.4/s, q = 5 (not the model's law); "
                             "report only", **common))
        frames = frames_by_time(os.path.join(args.out, name))
        folds = fold_analysis(frames[-1][1])
        wx, wy = folds["walls"]["x"], folds["walls"]["y"]
        rows.append(fpmv.row(PROBLEM, "fold length 2H (middle lines of both walls)", two_h, folds["fold_length"],
                             TOL_FOLD if tested else None, unit="m",
                             note="%s (%d of %d lobes in phase); wall x: %d lobes, 2H %.1f mm; wall y: "
                             "%d lobes, 2H %.1f mm; deepest lobe %.0f mm (about H)" % (
                                 folds["mode"], folds["in_phase"], folds["lobes_x"],
                                 len(wx["lobes"]), wx["fold_length"] * 1e3,
                                 len(wy["lobes"]), wy["fold_length"] * 1e3, folds["depth"] * 1e3), **common))
        rows.append(fpmv.row(PROBLEM, "final crush", 0.0, cs["crush"], None, relative=False, unit="m",
                             note="block stopped at %.2f ms%s; report only" % (
                                 cs["stop_time"] * 1e3, "" if cs["stopped"] else " (NOT stopped)"),
                             **common))
        rows.append(fpmv.row(PROBLEM, "peak striker force (full tube)", 0.0, cs["peak_force"] / 1e3,
                             None, relative=False, unit="kN", note="report only", **common))
        ps = s["plastic_strain"]
        rows.append(fpmv.row(PROBLEM, "peak plastic strain, outer surface", 1.502, ps["max_top"], None,
                             note="the paper: 1.502 at 13.4 ms (which surface unclear); report only",
                             **common))
        rows.append(fpmv.row(PROBLEM, "peak plastic strain, inner surface", 1.348, ps["max_bottom"], None,
                             note="the paper: 1.348 at 13.4 ms; report only", **common))
        last = {k: v[-1] for k, v in e.items()}
        rows.append(fpmv.row(PROBLEM, "share of the impact energy in plastic work", 1.0,
                             last["plastic"] / ke0, None,
                             note="kinetic %.3f, elastic %.3f, contact %.3f of it at the end; report only" % (
                                 last["kinetic"] / ke0, (last["internal"] - last["plastic"]) / ke0,
                                 last["contact"] / ke0), **common))
    if not args.quick:
        # The shapes at the paper's times from the finest mesh that kept those frames (the
        # 30 x 128 run lost its frames 1-85, 0.5-42.5 ms, to a restarted run: validation README);
        # a finest mesh without them gets its own figure at the times it has.
        names = ["%dx%d" % m for m in meshes]
        whole = [n for n in names if has_frames_at(os.path.join(args.out, n), PAPER_TIMES)]
        if whole:
            draw_shapes(shapes, os.path.join(args.out, whole[-1]), title_mesh=whole[-1])
        if names[-1] not in whole:
            kept = [t for t, _ in frames_by_time(os.path.join(args.out, names[-1])) if t > 0]
            late = [kept[0] + k * (kept[-1] - kept[0]) / 4 for k in range(4)]
            draw_shapes(fpmv.plot_path(PROBLEM + "-shapes-%s.png" % names[-1]), os.path.join(args.out, names[-1]),
                        times=late, title_mesh=names[-1])
    draw(plot, runs, p_aj_jc)
    return fpmv.finish(args.out, rows)


def draw(path, runs, p_aj):
    plt = fpmv.pyplot()
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    for name, res in sorted(runs.items()):
        h = res["history"]
        t = [x * 1e3 for x in h["time"]]
        ax1.plot(t, [4 * f / 1e3 for f in h["striker_force"]], lw=0.8, label="striker force, mesh " + name)
        ax2.plot(t, [a / 9.81 for a in h["a_end_az"]], lw=0.6, label="point A, mesh " + name)
        cs = crush_summary(h)
        ax1.axhline(cs["mean_force"] / 1e3, ls="--", lw=0.8, color="k")
    ax1.axhline(p_aj / 1e3, ls=":", lw=1.2, color="r", label="Abramowicz-Jones (JC rate factor)")
    ax1.set_ylabel("force on the block, full tube [kN]")
    ax1.legend(fontsize=8)
    ax1.grid(alpha=0.3)
    ax2.set_ylabel("axial acceleration at A [g]")
    ax2.set_xlabel("time [ms]")
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3)
    fig.suptitle("Square tube 100 x 100 x 3 mm, 800 kg at 9.5 m/s (dashed: mean force)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


PAPER_TIMES = (3.5e-3, 9.6e-3, 12.8e-3, 17.4e-3)  # the paper's figure of the deformed tube


def draw_shapes(path, out_dir, times=PAPER_TIMES, final=True, title_mesh=""):
    """Top: the whole tube (the quarter mirrored) at the paper's four times and at the end,
    coloured by the equivalent plastic strain of the outer surface and shaded by the light.
    Bottom: the middle lines of the walls x = b/2 and y = b/2 (the outward deflection against
    the current z)."""
    plt = fpmv.pyplot()
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    import matplotlib.cm as cm
    import numpy as np
    frames = frames_by_time(out_dir)
    chosen = [min(frames, key=lambda f: abs(f[0] - want)) for want in times]
    if final:
        chosen.append(frames[-1])
    n = len(chosen)
    fig = plt.figure(figsize=(3.2 * n, 11))
    grid = fig.add_gridspec(2, n, height_ratios=[1.6, 1.0], hspace=0.05, wspace=0.05)
    light = np.array([0.5, -0.7, 0.5]) / np.linalg.norm([0.5, -0.7, 0.5])
    for k, (tf, fp) in enumerate(chosen):
        d = fpmv.read_vtu(fp)
        pts = np.array(d["points"]) * 1e3
        conn = np.array(d["connectivity"]).reshape(-1, 3)
        ep = np.array(d["plastic_strain_top"])
        polys, colors = [], []
        for sx in (1, -1):
            for sy in (1, -1):
                p = pts * np.array([sx, sy, 1])
                tri = p[conn]
                nrm = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
                nrm /= np.linalg.norm(nrm, axis=1)[:, None] + 1e-30
                shade = 0.35 + 0.65 * np.abs(nrm @ light)
                rgba = cm.viridis(np.clip(ep, 0, 1.0))
                rgba[:, :3] *= shade[:, None]
                polys.extend(tri)
                colors.extend(rgba)
        ax = fig.add_subplot(grid[0, k], projection="3d")
        ax.add_collection3d(Poly3DCollection(polys, facecolors=colors, edgecolors="none"))
        ax.set_xlim(-75, 75)
        ax.set_ylim(-75, 75)
        ax.set_zlim(0, 400)
        ax.set_box_aspect((1, 1, 2.6), zoom=1.2)
        ax.view_init(elev=14, azim=-55)
        ax.set_title("t = %.1f ms" % (tf * 1e3), fontsize=10)
        ax.set_axis_off()
        # middle lines of the walls x = b/2 and y = b/2
        x0 = pts - np.array(d["displacement"]) * 1e3
        ax2 = fig.add_subplot(grid[1, k])
        for across, along, style, label in ((1, 0, "k.-", "wall x"), (0, 1, "r.-", "wall y")):
            on = (np.abs(x0[:, across]) < 1e-6) & (np.abs(x0[:, along] - B * 1e3 / 2) < 1e-6)
            order = np.argsort(x0[on, 2])
            ax2.plot(pts[on][order, along] - B * 1e3 / 2, pts[on][order, 2], style, lw=0.8, ms=2, label=label)
        if k == 0:
            ax2.legend(fontsize=7, loc="lower left")
        ax2.set_xlim(-40, 40)
        ax2.set_ylim(0, 400)
        ax2.set_aspect("equal")
        ax2.grid(alpha=0.3)
        ax2.set_xlabel("outward deflection [mm]")
        if k == 0:
            ax2.set_ylabel("z [mm] (middle lines of the walls)")
    sm = cm.ScalarMappable(cmap="viridis")
    sm.set_clim(0, 1.0)
    fig.colorbar(sm, ax=fig.axes[0::2], shrink=0.4, location="right", pad=0.01,
                 label="equivalent plastic strain, outer surface (clipped at 1)")
    if title_mesh:
        fig.suptitle("mesh %s (quarter model, mirrored)" % title_mesh, fontsize=11)
    fig.savefig(path, dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())

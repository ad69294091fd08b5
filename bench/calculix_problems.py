"""The problems of bench/calculix_compare.py and their input files: the spherical cap (the paper's
model III and finer) and the clamped plate, their meshes (S3, and S6 with midside nodes), the
fpmshell model and the CalculiX deck of each run."""
import math
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
CAP_EXAMPLE = REPO / "examples" / "spherical_cap_elastic" / "model.yaml"


# --------------------------------------------------------------------------------------------
# Problems: geometry, data, mesh
# The cap is compared on the paper's model III (14 rings) and twice as fine, whatever mesh the
# example runs (a CalculiX S6 run of the example's 40 rings takes hours).
PAPER_MODEL_III_RINGS = 14
# --------------------------------------------------------------------------------------------

def cap_problem():
    """The elastic spherical cap; every number from the example model (benchmarks.md 5.1)."""
    try:
        import yaml
    except ImportError:
        sys.exit("error: PyYAML is needed to read %s (use /usr/bin/python3 or pip install "
                 "pyyaml)" % CAP_EXAMPLE)
    m = yaml.safe_load(CAP_EXAMPLE.read_text())
    mat = next(iter(m["materials"].values()))
    load = m["loads"][0]
    curve = m["curves"][load["curve"]]
    if not all(abs(f - 1.0) < 1e-12 for _, f in curve) or m.get("damping"):
        sys.exit("error: %s no longer applies a held step pressure without damping; "
                 "update this script" % CAP_EXAMPLE)
    g = m["mesh"]
    if g.get("generator") != "spherical_cap" or float(g.get("sector_deg", 360)) != 360:
        sys.exit("error: %s is no longer the full-cap generator model" % CAP_EXAMPLE)
    return {
        "name": "cap",
        "title": "clamped spherical cap, step pressure (benchmarks.md 5.1)",
        "unit": "in",
        "radius": float(g["radius"]),
        "half_angle_deg": float(g["half_angle_deg"]),
        "example_rings": PAPER_MODEL_III_RINGS,
        "thickness": float(m["sections"][0]["thickness"]),
        "density": float(mat["density"]),
        "E": float(mat["youngs_modulus"]),
        "nu": float(mat["poisson_ratio"]),
        "pressure": float(load["value"]),
        "end_time": float(m["control"]["end_time"]),
        "time_step_scale": float(m["control"].get("time_step_scale", 0.9)),
        "bending": m["control"].get("bending", "bciz"),
        "monitor": "APEX",
        "clamped": "RIM",
        "sizes": [PAPER_MODEL_III_RINGS, 2 * PAPER_MODEL_III_RINGS],
        "s6_sizes": [PAPER_MODEL_III_RINGS],
        "quick_size": 6,           # the paper's model I (127 nodes)
        "quick_s6": True,          # 2600 C3D15 increments: about 15 s
        "quick_end_time": 0.5e-3,  # past the first peak (0.33-0.40 ms)
        "mesh": cap_mesh,
        "size_name": "rings",
    }


def plate_problem():
    """The clamped square plate of validation/plate_clamped, loaded by a step pressure."""
    return {
        "name": "plate",
        "title": "clamped square plate, step pressure (benchmarks.md 2, dynamic)",
        "unit": "m",
        "length": 1.0,
        "thickness": 0.01,
        "density": 7850.0,
        "E": 2.1e11,
        "nu": 0.3,
        "pressure": 100.0,
        "end_time": 12e-3,
        "time_step_scale": 0.9,
        "bending": "bciz",
        "monitor": "CENTRE",
        "clamped": "EDGES",
        "sizes": [8, 16],
        "s6_sizes": [8],           # C3D15 needs a much smaller step here (minutes of CPU)
        "quick_size": 8,
        "quick_s6": False,         # C3D15 step 1.9e-7 s: 42 000 increments, minutes
        "quick_end_time": 8e-3,    # past the first peak (T/2 = 5.6 ms; 6 ms on 8 x 8)
        "mesh": plate_mesh,
        "size_name": "squares per side",
    }


def cap_mesh(p, n):
    """fpmshell's `spherical_cap` generator (src/fpmshell/mesh/generators.cpp), full cap.

    Node 0 is the apex; ring k (1..n) has 6k nodes at polar angle alpha k / n, starting at
    azimuth 0. Rings k-1 and k are joined by walking both from azimuth 0 and always advancing
    the ring whose next node comes first (integer comparison, as in the generator), which
    gives triangles counter-clockwise about the outward normal.
    """
    radius, alpha = p["radius"], math.radians(p["half_angle_deg"])
    nodes = [(0.0, 0.0, radius)]
    first, segments = [0], [0]
    for k in range(1, n + 1):
        segments.append(6 * k)
        first.append(len(nodes))
        theta = alpha * k / n
        for q in range(6 * k):
            phi = 2.0 * math.pi * q / (6 * k)
            nodes.append((radius * math.sin(theta) * math.cos(phi),
                          radius * math.sin(theta) * math.sin(phi), radius * math.cos(theta)))

    def ring_node(k, q):
        if k == 0:
            return 0
        return first[k] + (0 if q == segments[k] else q)

    tris = []
    for k in range(1, n + 1):
        m_in, m_out = segments[k - 1], segments[k]
        pi = qo = 0
        while pi < m_in or qo < m_out:
            if pi == m_in:
                outer = True
            elif qo < m_out:
                outer = (qo + 1) * m_in < (pi + 1) * m_out
            else:
                outer = False
            if outer:
                tris.append((ring_node(k - 1, pi), ring_node(k, qo), ring_node(k, qo + 1)))
                qo += 1
            else:
                tris.append((ring_node(k - 1, pi), ring_node(k, qo), ring_node(k - 1, pi + 1)))
                pi += 1
    rim = [ring_node(n, q) for q in range(segments[n])]
    return np.array(nodes), tris, {"APEX": [0], "RIM": rim}


def plate_mesh(p, n):
    """Full a x a plate in z = 0, n x n squares, diagonals alternating (symmetric about the
    centre for even n), triangles counter-clockwise about +z."""
    if n % 2:
        raise ValueError("the plate needs an even number of squares per side (a centre node)")
    a = p["length"]
    nodes = [(a * i / n, a * j / n, 0.0) for j in range(n + 1) for i in range(n + 1)]

    def node(i, j):
        return j * (n + 1) + i

    tris = []
    for j in range(n):
        for i in range(n):
            n00, n10, n11, n01 = node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)
            if (i + j) % 2 == 0:
                tris += [(n00, n10, n11), (n00, n11, n01)]
            else:
                tris += [(n00, n10, n01), (n10, n11, n01)]
    edges = sorted({node(i, j) for j in range(n + 1) for i in range(n + 1)
                    if i in (0, n) or j in (0, n)})
    return np.array(nodes), tris, {"CENTRE": [node(n // 2, n // 2)], "EDGES": edges}


def with_midside_nodes(nodes, tris, sets):
    """S6 version of a triangle mesh: one node at the midpoint of each edge (so each facet
    stays the flat triangle fpmshell sees); a set gets the mid-side nodes of its edges."""
    nodes = [tuple(x) for x in nodes]
    mid = {}

    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in mid:
            mid[key] = len(nodes)
            nodes.append(tuple(0.5 * (nodes[a][i] + nodes[b][i]) for i in range(3)))
        return mid[key]

    elements = [(a, b, c, midpoint(a, b), midpoint(b, c), midpoint(c, a)) for a, b, c in tris]
    sets6 = {}
    for name, members in sets.items():
        inside = set(members)
        sets6[name] = list(members) + sorted(v for (a, b), v in mid.items()
                                             if a in inside and b in inside)
    return np.array(nodes), elements, sets6


# --------------------------------------------------------------------------------------------
# Input files
# --------------------------------------------------------------------------------------------

def ccx_number(value, scale):
    """A coordinate as ccx can read it. ccx reads each number of a card with a 20-character
    Fortran format and silently cuts a longer field: '-2.71834490381953e-16' (the round-off
    of cos 90 deg at 15 digits) became -0.27, moved a node by 0.27 in and made ccx's stable
    step 40 times smaller. Hence round-off below 1e-12 of the model size is written as 0 and
    12 significant digits are kept (at most 18 characters)."""
    text = "%.12g" % (0.0 if abs(value) < 1e-12 * scale else value)
    assert len(text) <= 20, text
    return text


def write_mesh_inp(path, nodes, elements, etype, sets, comment):
    """Abaqus-style mesh file: nodes and elements numbered from 1, node sets."""
    lines = ["** " + c for c in comment]
    lines.append("*NODE, NSET=NALL")
    scale = float(np.max(np.abs(nodes)))
    lines += ["%d, %s" % (i + 1, ", ".join(ccx_number(v, scale) for v in x))
              for i, x in enumerate(nodes)]
    lines.append("*ELEMENT, TYPE=%s, ELSET=EALL" % etype)
    lines += ["%d, %s" % (e + 1, ", ".join(str(v + 1) for v in el))
              for e, el in enumerate(elements)]
    for name, members in sets.items():
        lines.append("*NSET, NSET=%s" % name)
        members = [m + 1 for m in members]
        lines += [", ".join(map(str, members[i:i + 12])) for i in range(0, len(members), 12)]
    Path(path).write_text("\n".join(lines) + "\n")


def write_fpmshell_model(path, p, end_time):
    """fpmshell model on mesh.inp (model-format.md); the mesh file's sets name the rim/apex."""
    every = end_time / 1000.0  # history rows; of the order of the step, so peaks are sampled
    text = f"""title: {p['title']}, CalculiX comparison (bench/calculix_compare.py)
mesh: {{file: mesh.inp}}
materials:
  mat: {{type: elastic, density: {p['density']!r}, youngs_modulus: {p['E']!r},
        poisson_ratio: {p['nu']!r}}}
sections:
  - {{elements: all, material: mat, thickness: {p['thickness']!r}}}
boundary:
  - {{nodes: {p['clamped']}, fix: all}}
curves:
  step: [[0, 1], [1, 1]]
loads:
  - {{type: pressure, elements: all, value: {p['pressure']!r}, curve: step}}   # against the normal
control:
  end_time: {end_time!r}
  time_step_scale: {p['time_step_scale']!r}
  bending: {p['bending']}
output:
  every: {every!r}
  fields_every: {end_time!r}   # first and last frame only: the timing is the solver's
  histories:
    - {{name: w, nodes: {p['monitor']}, quantity: uz}}
"""
    Path(path).write_text(text)


def write_ccx_deck(path, p, mesh_file, end_time, dt_max):
    """CalculiX explicit-dynamics deck on the mesh file (settings: see the module docstring)."""
    def g(x):  # 12 digits: short enough for ccx's 20-character fields (see ccx_number)
        return "%.12g" % x

    step_line = "%s, %s" % (g(end_time / 1e4), g(end_time))
    if dt_max:
        step_line += ", , %s" % g(dt_max)  # 4th field: the largest increment ccx may take
    text = f"""** {p['title']}: CalculiX deck written by bench/calculix_compare.py
*INCLUDE, INPUT={mesh_file}
*MATERIAL, NAME=MAT
*ELASTIC
{g(p['E'])}, {g(p['nu'])}
*DENSITY
{g(p['density'])}
*SHELL SECTION, ELSET=EALL, MATERIAL=MAT, OFFSET=0
{g(p['thickness'])}
*BOUNDARY
{p['clamped']}, 1, 6
*AMPLITUDE, NAME=HELD
0., 1., 1., 1.
** NLGEOM: large displacements (fpmshell is geometrically nonlinear); INC: no increment limit
*STEP, NLGEOM, INC=10000000
*DYNAMIC, EXPLICIT
{step_line}
** ccx's shell pressure acts along the element normal, fpmshell's against it: hence -p
*DLOAD, AMPLITUDE=HELD
EALL, P, {g(-p['pressure'])}
*NODE PRINT, NSET={p['monitor']}, FREQUENCY=1
U
*END STEP
"""
    Path(path).write_text(text)

"""LS-DYNA keyword decks run as they are (docs/decks.md):

- every test deck of examples/decks gives the same history.csv as its YAML twin (written by
  hand), byte for byte: the same model through two readers;
- `fpmshell convert` writes a YAML model that runs to the same history.csv again;
- `fpmshell check DECK` prints the deck as understood (materials, sections, conditions, bodies)
  and the notes on what was ignored.
Refusals, notes and messages of small decks are in deck_messages_test.py.

usage: deck_test.py FPMSHELL WORKDIR
"""
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECKS = os.path.join(ROOT, "examples", "decks")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_twins  # noqa: E402
from deck_twins import (check_erodes, deck_against_twin, fpmshell, read, run,  # noqa: E402
                        write_case)

FPM, WORK = deck_twins.start(sys.argv)



# ---- the test decks against their twins, and through convert
for name in sorted(d for d in os.listdir(DECKS) if os.path.isdir(os.path.join(DECKS, d))):
    deck = os.path.join(DECKS, name, name + ".k")
    twin = os.path.join(DECKS, name, name + ".yaml")
    r_deck, h_deck = run(deck, os.path.join(WORK, name, "deck"))
    check(f"{name}: the deck runs", r_deck.returncode == 0, r_deck.stderr)
    r_twin, h_twin = run(twin, os.path.join(WORK, name, "twin"))
    check(f"{name}: the twin runs", r_twin.returncode == 0, r_twin.stderr)
    if r_deck.returncode or r_twin.returncode:
        continue
    check(f"{name}: deck and twin give the same history.csv", read(h_deck) == read(h_twin),
          "the files differ")
    lines = read(h_deck).splitlines()
    check(f"{name}: the history has rows and moves", len(lines) > 10 and
          any(float(v) != 0 for v in lines[-1].split(",")[1:]), lines[-1])
    converted = os.path.join(WORK, name, "converted.yaml")
    c = fpmshell("convert", deck, "-o", converted)
    check(f"{name}: convert", c.returncode == 0 and os.path.exists(converted), c.stderr)
    r_conv, h_conv = run(converted, os.path.join(WORK, name, "converted"))
    check(f"{name}: the converted model gives the same history.csv",
          r_conv.returncode == 0 and read(h_conv) == read(h_deck), r_conv.stderr)
    again = fpmshell("convert", deck, "-o", converted)
    check(f"{name}: convert does not replace a file without --overwrite",
          again.returncode == 2 and "--overwrite" in again.stderr, again.stderr)

# ---- pressures on segments: the shells' own pressure, whichever way each segment runs round
# its shell (a segment against the shell's normal pushes the other way)
PANEL = os.path.join(DECKS, "pressure_panel")
panel_deck = read(os.path.join(PANEL, "pressure_panel.k"))
shell_load = "*LOAD_SHELL_SET\n$#    ssid      lcid        sf        at\n         7         1   20000.0\n"
mesh_lines = read(os.path.join(PANEL, "pressure_panel_mesh.k")).splitlines()
first = mesh_lines.index("*ELEMENT_SHELL") + 1
shells = []
for line in mesh_lines[first:]:
    if line.startswith("*"):
        break
    shells.append([int(line[8 * k:8 * k + 8]) for k in (0, 2, 3, 4, 5)])


def segment_card(nodes):
    return "".join(f"{n:10d}" for n in nodes) + "\n"


def panel_variant(name, load_cards):
    folder = os.path.join(WORK, "segments", name)
    os.makedirs(folder, exist_ok=True)
    shutil.copy(os.path.join(PANEL, "pressure_panel_mesh.k"), folder)
    assert shell_load in panel_deck
    path = os.path.join(folder, "pressure_panel.k")
    with open(path, "w") as f:
        f.write(panel_deck.replace(shell_load, load_cards))
    return path


def columns_by_name(path):
    """The columns of a history.csv by their header names, as numbers."""
    rows = [line.split(",") for line in read(path).splitlines()]
    return {name: [float(r[k]) for r in rows[1:]] for k, name in enumerate(rows[0])}


def history_columns(path):
    rows = [line.split(",") for line in read(path).splitlines()[1:]]
    return list(zip(*[[float(v) for v in row] for row in rows]))


reference = os.path.join(WORK, "pressure_panel", "deck", "history.csv")
aligned = "*SET_SEGMENT\n         3\n" + "".join(segment_card(e[1:]) for e in shells)
reversed_ = "*SET_SEGMENT_TITLE\nback faces\n         4\n" + "".join(
    segment_card(e[1:][::-1]) for e in shells)
VARIANTS = {  # name: (load cards, equal to the shell-set load bit for bit)
    "segment set": (aligned + "*LOAD_SEGMENT_SET\n         3         1   20000.0\n", True),
    "reversed segment set": (reversed_ + "*LOAD_SEGMENT_SET\n         4         1  -20000.0\n", True),
    "single segments, half reversed": ("*LOAD_SEGMENT\n" + "".join(
        f"{1:10d}{(20000.0 if k % 2 else -20000.0):10.1f}{0:10d}" +
        segment_card(e[1:] if k % 2 else e[1:][::-1])[:40] + "\n" for k, e in enumerate(shells)),
        False),
}
for name, (cards, exact) in VARIANTS.items():
    path = panel_variant(name.replace(" ", "_").replace(",", ""), cards)
    r, h = run(path, os.path.join(os.path.dirname(path), "out"))
    check(f"{name}: runs", r.returncode == 0, r.stderr)
    if r.returncode:
        continue
    if exact:
        check(f"{name}: the history of the shell-set pressure, bit for bit",
              read(h) == read(reference), "the files differ")
    else:  # two loads add the same element forces in another order: equal to rounding
        got, want = history_columns(h), history_columns(reference)
        worst = max(abs(a - b) / (max(abs(x) for x in w) or 1.0)
                    for g, w in zip(got, want) for a, b in zip(g, w))
        check(f"{name}: the history of the shell-set pressure to rounding", worst < 1e-9,
              f"largest difference {worst:.3g} of a column's largest value")

# ---- *MAT_POWER_LAW_PLASTICITY: the strip of strip_pull.k in a power-law steel, against the
# twin with the same material written in YAML
STRIP = os.path.join(DECKS, "strip_pull")
strip_deck, strip_twin = read(os.path.join(STRIP, "strip_pull.k")), read(os.path.join(STRIP, "strip_pull.yaml"))
mat_024 = strip_deck[strip_deck.index("*MAT_PIECEWISE_LINEAR_PLASTICITY"):strip_deck.index("*DEFINE_TABLE")]
mat_018 = ("*MAT_POWER_LAW_PLASTICITY\n"
           "         1    7850.0   2.1e+11       0.3   9.0e+08      0.25     40.40       5.0\n"
           "   3.0e+08\n")
yaml_024 = strip_twin[strip_twin.index("  steel:"):strip_twin.index("sections:")]
yaml_018 = ("  steel: {type: power_law, density: 7850, youngs_modulus: 2.1e11, poisson_ratio: 0.3,\n"
            "          k: 9.0e8, n: 0.25, yield_stress: 3.0e8, cowper_symonds: {D: 40.4, q: 5}}\n\n")
folder = os.path.join(WORK, "power_law")
h_deck = deck_against_twin("power law", folder, os.path.join(STRIP, "strip_pull_mesh.k"),
                           strip_deck.replace(mat_024, mat_018),
                           strip_twin.replace(yaml_024, yaml_018))
if h_deck:
    summary = read(os.path.join(folder, "deck", "summary.json"))
    check("power law: the strip yields", '"plastic_work"' in summary and
          float(summary.split('"plastic_work"')[1].split(":")[1].split(",")[0]) > 0, summary[:400])

# ---- *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (037): the strip in a sheet steel of
# Lankford ratio 2 on a flow curve (HLCID), against its twin (normal_anisotropy, flow_curve); an
# R < 0 read as its magnitude (noted); the same strip with R = 1 is another run
mat_037 = ("*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC\n"
           "$#     mid        ro         e        pr      sigy      etan         r     hlcid\n"
           "         1    7850.0   2.1e+11       0.3       0.0       0.0      -2.0        77\n"
           "*DEFINE_CURVE\n        77\n                 0.0             3.0e+08\n"
           "                 0.1             4.0e+08\n                 0.5             5.0e+08\n")
yaml_037 = ("  steel: {type: tabulated, density: 7850, youngs_modulus: 2.1e11, poisson_ratio: 0.3,\n"
            "          normal_anisotropy: 2, flow_curve: [[0, 3.0e8], [0.1, 4.0e8], [0.5, 5.0e8]]}\n\n")
folder = os.path.join(WORK, "mat_037")
h_hill = deck_against_twin("*MAT_037", folder, os.path.join(STRIP, "strip_pull_mesh.k"),
                           strip_deck.replace(mat_024, mat_037),
                           strip_twin.replace(yaml_024, yaml_037))
c = fpmshell("check", os.path.join(folder, "model.k"))
check("*MAT_037: R < 0 is noted", "R < 0 read as its magnitude 2" in c.stdout + c.stderr,
      c.stdout + c.stderr)
folder = os.path.join(WORK, "mat_037_r1")
h_iso = deck_against_twin("*MAT_037 with R = 1", folder, os.path.join(STRIP, "strip_pull_mesh.k"),
                          strip_deck.replace(mat_024, mat_037.replace("-2.0", " 1.0")),
                          strip_twin.replace(yaml_024, yaml_037.replace("anisotropy: 2",
                                                                        "anisotropy: 1")))
check("*MAT_037: R = 2 and R = 1 are different runs",
      h_hill and h_iso and read(h_hill) != read(h_iso), "the same history")

# ---- geometric rigid walls: plate_drop.k on a fixed sphere and on a finite flat face, against
# its twin with the same body written in YAML
DROP = os.path.join(DECKS, "plate_drop")
drop_deck, drop_twin = read(os.path.join(DROP, "plate_drop.k")), read(os.path.join(DROP, "plate_drop.yaml"))
planar = drop_deck[drop_deck.index("*RIGIDWALL_PLANAR_ID"):drop_deck.index("*CONTROL_TERMINATION")]

# ---- ICID: plate_drop.k's velocity given in a local system whose x axis is the global -z
# (*DEFINE_COORDINATE_SYSTEM, or _VECTOR): the same model as the twin's global velocity
generation = ("         1         2       0.0       0.0       0.0      -5.0\n")
assert generation in drop_deck
for name, system in {
        "_SYSTEM": ("*DEFINE_COORDINATE_SYSTEM\n         7       0.0       0.0       0.0       0.0"
                    "       0.0      -1.0\n       1.0       0.0       0.0\n"),
        "_VECTOR": ("*DEFINE_COORDINATE_VECTOR\n         7       0.0       0.0      -1.0       1.0"
                    "       0.0       0.0\n")}.items():
    local = drop_deck.replace(generation, "         1         2       0.0       5.0       0.0"
                              "       0.0         0         7\n").replace("*END", system + "*END")
    deck_against_twin(f"ICID in a local system ({name})", os.path.join(WORK, "icid" + name),
                      os.path.join(DROP, "plate_drop_mesh.k"), local, drop_twin)

twin_body = "  - {name: floor, point: [0, 0, 0], normal: [0, 0, 1], fixed: true}\n"
WALLS = {  # name: (deck card, twin body)
    "sphere": ("*RIGIDWALL_GEOMETRIC_SPHERE_ID\n         1ball\n         0\n"
               "      0.05      0.05      -0.1       0.0       0.0       0.0\n       0.1\n",
               "  - {name: floor, shape: sphere, point: [0.05, 0.05, -0.1], radius: 0.1, fixed: true}\n"),
    "flat": ("*RIGIDWALL_GEOMETRIC_FLAT_DISPLAY\n         0\n"
             "       0.0       0.0       0.0       0.0       0.0       1.0\n"
             "       1.0       0.0       0.0      0.05       1.0\n         5\n",
             "  - {name: floor, point: [0, 0, 0], normal: [0, 0, 1], edge: [1, 0, 0],\n"
             "     size: [0.05, 1], fixed: true}\n"),
    # a cylinder along y driven up at 3 m/s by a straight displacement curve
    "moving cylinder": ("*RIGIDWALL_GEOMETRIC_CYLINDER_MOTION\n         0\n"
                        "      0.05       0.0      -0.1      0.05       1.0      -0.1\n"
                        "       0.1       0.0\n         7         1       0.0       0.0       2.0\n"
                        "*DEFINE_CURVE\n         7\n                 0.0                 0.0\n"
                        "                0.01                0.03\n",
                        "  - {name: floor, shape: cylinder, point: [0.05, 0, -0.1], axis: [0, 1, 0],\n"
                        "     radius: 0.1, fixed: true, velocity: [0, 0, 3]}\n"),
}
for name, (card, body) in WALLS.items():
    assert planar in drop_deck and twin_body in drop_twin
    h_deck = deck_against_twin(f"{name} wall", os.path.join(WORK, "walls", name.replace(" ", "_")),
                               os.path.join(DROP, "plate_drop_mesh.k"),
                               drop_deck.replace(planar, card), drop_twin.replace(twin_body, body))
    if not h_deck:
        continue
    forces = [float(line.split(",")[-1]) for line in read(h_deck).splitlines()[1:]]
    check(f"{name} wall: the plate hits it", min(forces) < 0, f"smallest force {min(forces)}")

# ---- *RIGIDWALL_PLANAR FRIC: plate_drop.k thrown sideways onto a floor with friction 0.3, and
# with FRIC = 1 (no sliding), against the twin with the contact's friction written in YAML
fric_line = "       0.0       0.0       0.0       0.0       0.0       1.0       0.0\n"
speed_line = "         1         2       0.0       0.0       0.0      -5.0\n"
assert fric_line in planar and speed_line in drop_deck
assert "  - {type: rigid, body: floor, offset: 0}" in drop_twin
sideways = drop_deck.replace(speed_line, "         1         2       0.0       4.0       0.0      -5.0\n")
sideways_twin = drop_twin.replace("velocity: [0, 0, -5]", "velocity: [4, 0, -5]")
for fric, written in (("0.3", "0.3"), ("1.0", "stick")):
    h_deck = deck_against_twin(
        f"wall friction {fric}", os.path.join(WORK, "walls", "friction_" + fric),
        os.path.join(DROP, "plate_drop_mesh.k"),
        sideways.replace(fric_line, fric_line.replace("       0.0\n", f"{fric:>10}\n")),
        sideways_twin.replace("  - {type: rigid, body: floor, offset: 0}",
                              f"  - {{type: rigid, body: floor, offset: 0, friction: {written}}}"))
    if not h_deck:
        continue
    columns = columns_by_name(h_deck)
    fx, fz = columns["rigidwall1_force_x"], columns["rigidwall1_force_z"]
    check(f"wall friction {fric}: the floor is dragged along the sliding (+x)",
          max(fx) > 0 and sum(fx) > 0, f"force_x from {min(fx)} to {max(fx)}")
    if fric == "0.3":  # Coulomb: |F_x| <= mu |F_z| in every row (to rounding)
        over = [(x, z) for x, z in zip(fx, fz) if abs(x) > 0.3 * abs(z) * (1 + 1e-9) + 1e-9]
        check("wall friction 0.3: within the Coulomb cone in every row", not over, str(over[:3]))

# ---- *CONSTRAINED_NODAL_RIGID_BODY, *CONSTRAINED_SPOTWELD, *CONSTRAINED_GENERALIZED_WELD_SPOT:
# plate_drop.k thrown sideways with a corner made rigid and two welds, against the twin with the
# same constraints written in YAML
constrained = sideways.replace("*RIGIDWALL_PLANAR_ID", (
    "*SET_NODE_LIST\n         7\n         1         2         3        10        11\n"
    "*SET_NODE_LIST\n         8\n        60        61\n"
    "*CONSTRAINED_NODAL_RIGID_BODY\n         1                   7\n"
    "*CONSTRAINED_SPOTWELD\n        41        42   1.0e+04\n"
    "*CONSTRAINED_GENERALIZED_WELD_SPOT\n         8\n       0.0       0.0\n"
    "*RIGIDWALL_PLANAR_ID"))
constrained_twin = sideways_twin.replace("sets:\n", (
    "sets:\n  nrb: {node_ids: [1, 2, 3, 10, 11]}\n  weld: {node_ids: [41, 42]}\n"
    "  generalized: {node_ids: [60, 61]}\n")).replace("rigid_bodies:\n", (
    "constraints:\n  - {type: rigid, nodes: nrb}\n  - {type: rigid, nodes: weld}\n"
    "  - {type: rigid, nodes: generalized}\n\nrigid_bodies:\n")).replace(
    "  - {type: rigid, nodes: weld}\n", "  - {type: rigid, nodes: weld, failure: {normal_force: 1.0e4}}\n")
h_deck = deck_against_twin("constraints", os.path.join(WORK, "constraints"),
                           os.path.join(DROP, "plate_drop_mesh.k"), constrained, constrained_twin)
r = fpmshell("check", os.path.join(WORK, "constraints", "model.k"))
check("constraints: check names the bodies and notes the weld's blank exponent",
      r.returncode == 0 and "nodal rigid bodies: 3 (9 particles)" in r.stdout and
      "N or M blank: the exponent 2 is taken" in r.stdout, r.stdout + r.stderr)

# ---- *MAT_RIGID: clamped_beam.k with its four middle quadrangles a rigid part, against the twin
# with the rigid material written in YAML
BEAM = os.path.join(DECKS, "clamped_beam")
beam_deck, beam_twin = read(os.path.join(BEAM, "clamped_beam.k")), read(os.path.join(BEAM, "clamped_beam.yaml"))
mesh_lines, in_shells = [], False
for line in read(os.path.join(BEAM, "clamped_beam_mesh.k")).splitlines():
    if line.startswith("*"):
        in_shells = line.startswith("*ELEMENT_SHELL")
    elif in_shells and line.strip() and int(line.split()[0]) in (10, 11, 30, 31):
        fields = line.split()
        line = f"{fields[0]:>8}{2:>8}" + "".join(f"{n:>8}" for n in fields[2:])
    mesh_lines.append(line)
rigid_mesh = os.path.join(WORK, "rigid_part_mesh", "clamped_beam_mesh.k")
os.makedirs(os.path.dirname(rigid_mesh), exist_ok=True)
with open(rigid_mesh, "w") as f:
    f.write("\n".join(mesh_lines) + "\n")
beam_section = ("  - {elements: all, material: al6061, thickness: 0.005, thickness_points: 3, "
                "thickness_rule: gauss}\n")
assert "*BOUNDARY_SPC_SET" in beam_deck and beam_section in beam_twin and "sections:" in beam_twin
rigid_deck = beam_deck.replace("*BOUNDARY_SPC_SET", (
    "*PART\nhammer\n2,2,2\n*SECTION_SHELL\n2,16,,3\n0.005,0.005,0.005,0.005\n"
    "*MAT_RIGID\n         2    7800.0   2.1e+11       0.3\n*BOUNDARY_SPC_SET"))
rigid_twin = beam_twin.replace(beam_section, (
    "  - {elements: part_1, material: al6061, thickness: 0.005, thickness_points: 3, "
    "thickness_rule: gauss}\n"
    "  - {elements: part_2, material: hammer, thickness: 0.005, thickness_points: 3, "
    "thickness_rule: gauss}\n")).replace(
    "\nsections:", "  hammer: {type: rigid, density: 7800, youngs_modulus: 2.1e11, poisson_ratio: 0.3}\n"
    "\nsections:")
deck_against_twin("rigid part", os.path.join(WORK, "rigid_part"), rigid_mesh, rigid_deck, rigid_twin)
r = fpmshell("check", os.path.join(WORK, "rigid_part", "model.k"))
check("rigid part: check names one body of the part's 9 particles",
      r.returncode == 0 and "nodal rigid bodies: 1 (9 particles)" in r.stdout and
      "material mat_2: rigid, density 7800" in r.stdout, r.stdout + r.stderr)

# ---- *DATABASE_RCFORC: tube_crush.k with the forces of its self-contact as histories, against
# the twin with the same columns written in YAML (the contact after the wall's: contact_2)
TUBE = os.path.join(DECKS, "tube_crush")
tube_deck, tube_twin = read(os.path.join(TUBE, "tube_crush.k")), read(os.path.join(TUBE, "tube_crush.yaml"))
assert tube_deck.endswith("*END\n") and tube_twin.endswith("quantity: rigid_wall_force_z}\n")
h_deck = deck_against_twin(
    "contact forces", os.path.join(WORK, "rcforc"), os.path.join(TUBE, "tube_crush_mesh.k"),
    tube_deck[:-len("*END\n")] + "*DATABASE_RCFORC\n1.0e-5\n*END\n",
    tube_twin + "".join(f"    - {{name: contact1_force_{c}, quantity: contact_2_force_{c}}}\n"
                        for c in "xyz"))
if h_deck:
    columns = columns_by_name(h_deck)
    check("contact forces: the columns of RCFORC are in history.csv",
          all(f"contact1_force_{c}" in columns for c in "xyz"), list(columns))

# ---- *DATABASE_MATSUM: tube_crush.k with each part's rigid-body velocity (its momentum over its
# mass) as histories, against the twin with the same columns written in YAML (reduce: mass_mean)
h_deck = deck_against_twin(
    "part velocities", os.path.join(WORK, "matsum"), os.path.join(TUBE, "tube_crush_mesh.k"),
    tube_deck[:-len("*END\n")] + "*DATABASE_MATSUM\n1.0e-5\n*END\n",
    tube_twin + "".join(f"    - {{name: part1_v{c}, nodes: part_1, quantity: v{c}, reduce: mass_mean}}\n"
                        for c in "xyz"))
if h_deck:
    columns = columns_by_name(h_deck)
    check("part velocities: the tube starts at rest and is pushed down by the wall (vz < 0 at the end)",
          all(columns[f"part1_v{c}"][0] == 0 for c in "xyz") and columns["part1_vz"][-1] < 0,
          [columns["part1_vz"][k] for k in (0, -1)])

# ---- *MAT_JOHNSON_COOK with CP > 0: tube_crush.k's steel softened by adiabatic heating (M, TM,
# TR, CP; theory.md eq. 7.4-2), against the twin with thermal_softening; it changes the crush
CP_LINE = "$#      cp        pc     spall        it        d1        d2        d3        d4\n       0.0\n"
JC_TWIN = "    reference_strain_rate: 1.0\n"
assert CP_LINE in tube_deck and JC_TWIN in tube_twin
h_hot = deck_against_twin(
    "thermal softening", os.path.join(WORK, "thermal"), os.path.join(TUBE, "tube_crush_mesh.k"),
    tube_deck.replace(CP_LINE, CP_LINE.replace("       0.0\n", "     477.0\n")),
    tube_twin.replace(JC_TWIN, JC_TWIN + "    thermal_softening: {m: 1, melt_temperature: 1800, "
                      "room_temperature: 293, specific_heat: 477}\n"))
h_cold = deck_against_twin(
    "isothermal", os.path.join(WORK, "isothermal"), os.path.join(TUBE, "tube_crush_mesh.k"),
    tube_deck, tube_twin)
if h_hot and h_cold:
    hot, cold = columns_by_name(h_hot), columns_by_name(h_cold)
    def mean_force(c):
        return sum(abs(f) for f in c["rigidwall1_force_z"]) / len(c["rigidwall1_force_z"])
    # the crush heats the folds by tens of kelvin (T* ~ 0.02): a softer tube, by about 0.6 %
    check("thermal softening: the heated tube resists the wall less on average",
          mean_force(hot) < 0.998 * mean_force(cold), (mean_force(hot), mean_force(cold)))

# ---- *MAT_JOHNSON_COOK D1..D5: tube_crush.k's steel with Johnson-Cook damage (theory.md eq.
# 7.6-2), NUMINT 1, against the twin with failure: {johnson_cook, points}; the folds erode
DAMAGE_CARDS = ("       0.0       0.0       0.0       0.0      0.05       0.3      -1.5      0.01\n"
                "       0.0       0.0       1.0       0.0         1\n")
h_damage = deck_against_twin(
    "Johnson-Cook damage", os.path.join(WORK, "jc_damage"), os.path.join(TUBE, "tube_crush_mesh.k"),
    tube_deck.replace(CP_LINE, CP_LINE.replace("       0.0\n", DAMAGE_CARDS)),
    tube_twin.replace(JC_TWIN, JC_TWIN + "    failure: {johnson_cook: {D1: 0.05, D2: 0.3, D3: -1.5, "
                      "D4: 0.01, D5: 0, reference_strain_rate: 1}, points: 1}\n"))
check_erodes("Johnson-Cook damage: the tube's folds erode", h_damage)
r = subprocess.run([FPM, "check", os.path.join(WORK, "jc_damage", "model.k")], capture_output=True,
                   text=True)
check("Johnson-Cook damage: check notes EROD read as 0",
      r.returncode == 0 and "EROD != 0 read as 0" in r.stdout + r.stderr, r.stdout + r.stderr)

# ---- *MAT_024 FAIL: strip_pull.k's steel fails at a plastic strain of 1 % (theory.md §7.6),
# against the twin with failure: {plastic_strain}; elements erode (summary.json)
STRIP_MAT = "$#     mid        ro         e        pr      sigy\n         1    7850.0   2.1e+11       0.3   3.0e+08\n"
assert STRIP_MAT in strip_deck and "    poisson_ratio: 0.3\n    flow_curves:" in strip_twin
h_fail = deck_against_twin(
    "failure strain", os.path.join(WORK, "failure"), os.path.join(STRIP, "strip_pull_mesh.k"),
    strip_deck.replace(STRIP_MAT, STRIP_MAT.replace("sigy\n", "sigy      etan      fail\n").replace(
        "3.0e+08\n", "3.0e+08       0.0      0.01\n")),
    strip_twin.replace("    poisson_ratio: 0.3\n    flow_curves:",
                       "    poisson_ratio: 0.3\n    failure: {plastic_strain: 0.01}\n    flow_curves:"))
check_erodes("failure strain: the strip's elements erode", h_fail)
if h_fail:
    with open(os.path.join(os.path.dirname(h_fail), "energy.csv")) as f:
        header = f.readline()
    check("failure strain: energy.csv has the column eroded_internal", "eroded_internal" in header,
          header)
# FAIL 1e21, LS-DYNA's default written out (as pydyna's decks do): no criterion, the twin without
h_never = deck_against_twin(
    "failure strain 1e21", os.path.join(WORK, "failure_never"), os.path.join(STRIP, "strip_pull_mesh.k"),
    strip_deck.replace(STRIP_MAT, STRIP_MAT.replace("sigy\n", "sigy      etan      fail\n").replace(
        "3.0e+08\n", "3.0e+08       0.0   1.0e+21\n")), strip_twin)
if h_never:
    with open(os.path.join(os.path.dirname(h_never), "energy.csv")) as f:
        header = f.readline()
    check("failure strain 1e21: no criterion (energy.csv without eroded_internal)",
          "eroded_internal" not in header, header)

# ---- *MAT_024 TDEL: an element erodes once its step falls below it (its steps fall from
# 5.87e-7 to 5.82e-7 as the strip is drawn), as the twin's failure: {minimum_time_step}
h_tdel = deck_against_twin(
    "TDEL", os.path.join(WORK, "tdel"), os.path.join(STRIP, "strip_pull_mesh.k"),
    strip_deck.replace(STRIP_MAT, STRIP_MAT.replace("sigy\n", "sigy      etan      fail      tdel\n").replace(
        "3.0e+08\n", "3.0e+08       0.0       0.0   5.85e-7\n")),
    strip_twin.replace("    poisson_ratio: 0.3\n    flow_curves:",
                       "    poisson_ratio: 0.3\n    failure: {minimum_time_step: 5.85e-7}\n    flow_curves:"))
check_erodes("TDEL: the strip's elements erode below the step", h_tdel)
folder = write_case("tdel_bad", strip_deck.replace(STRIP_MAT, STRIP_MAT.replace(
    "sigy\n", "sigy      etan      fail      tdel\n").replace("3.0e+08\n", "3.0e+08       0.0       0.0     -1e-7\n")),
    os.path.join(STRIP, "strip_pull_mesh.k"))
r = subprocess.run([FPM, "check", os.path.join(folder, "model.k")], capture_output=True, text=True)
check("TDEL < 0 refused with exit 2 and one sentence",
      r.returncode == 2 and r.stderr.count("error:") == 1 and "TDEL must be >= 0" in r.stderr, r.stderr)

# ---- *MAT_ADD_DAMAGE_GISSMO: strip_pull.k's steel with GISSMO's failure strain against
# triaxiality (LCSDG), its regularization by element size (LCREGD), DMGEXP and NUMFIP, and its
# fading from the start (ECRIT and DCRIT 0, FADEXP 1), against the twin with failure: {tabulated}
# (theory.md eqs. 7.6-3, 7.6-6); elements erode
GISSMO = """*MAT_ADD_DAMAGE_GISSMO
$#     mid              dtyp     refsz    numfip
         1                 1       0.0       1.0
$#   lcsdg     ecrit    dmgexp     dcrit    fadexp    lcregd
       901       0.0       2.0       0.0       1.0       902
*DEFINE_CURVE
       901
               -0.33                0.03
                0.33                0.01
                0.67               0.008
*DEFINE_CURVE
       902
               0.001                 1.2
                0.01                 0.8
"""
GISSMO_CARD_2 = "       901       0.0       2.0       0.0       1.0       902"


def gissmo_twin(name, folder, card_2, curves, fading):
    """strip_pull.k with GISSMO whose card 2 is card_2 (and more *DEFINE_CURVEs), against the
    twin whose tabulated criterion has that `fading`; the deck's history file; its elements
    erode."""
    h = deck_against_twin(
        name, os.path.join(WORK, folder), os.path.join(STRIP, "strip_pull_mesh.k"),
        strip_deck.replace("*END\n", GISSMO.replace(GISSMO_CARD_2, card_2) + curves + "*END\n"),
        strip_twin.replace("    poisson_ratio: 0.3\n    flow_curves:",
                           "    poisson_ratio: 0.3\n    failure: {tabulated: {failure_strain: "
                           "[[-0.33, 0.03], [0.33, 0.01], [0.67, 0.008]], exponent: 2, "
                           "regularization: [[0.001, 1.2], [0.01, 0.8]], fading: " + fading +
                           "}, points: 1}\n    flow_curves:"))
    check_erodes(name + ": the strip's elements erode", h)
    return h


h_gissmo = gissmo_twin("GISSMO", "gissmo", GISSMO_CARD_2, "",
                       "{critical_damage: 0, exponent: 1}")
r = subprocess.run([FPM, "check", os.path.join(WORK, "gissmo", "model.k")], capture_output=True,
                   text=True)
check("GISSMO: check has no note on ECRIT, DCRIT or FADEXP (they are modelled)",
      r.returncode == 0 and "ECRIT" not in r.stdout + r.stderr, r.stdout + r.stderr)
# the instability at a critical strain against triaxiality (ECRIT < 0) and FADEXP 2
h_ecrit = gissmo_twin(
    "GISSMO ECRIT", "gissmo_ecrit", "       901    -903.0       2.0       0.0       2.0       902",
    "*DEFINE_CURVE\n       903\n               -0.33               0.015\n"
    "                0.67               0.004\n",
    "{critical_strain: [[-0.33, 0.015], [0.67, 0.004]], exponent: 2}")
# FADEXP < 0: the fading exponent a curve against the element size; ECRIT > 0 a constant
gissmo_twin(
    "GISSMO FADEXP curve", "gissmo_fadexp",
    "       901     0.006       2.0       0.0    -904.0       902",
    "*DEFINE_CURVE\n       904\n               0.001                 1.5\n"
    "                0.01                 3.0\n",
    "{critical_strain: 0.006, exponent: [[0.001, 1.5], [0.01, 3]]}")
check("GISSMO ECRIT: fading from an instability gives another history than fading from the start",
      h_ecrit is not None and h_gissmo is not None and read(h_ecrit) != read(h_gissmo))
# LCSRS (card 3): the failure strain's factor against the plastic strain rate as `rate_scaling`
# (a first rate < 0: logarithms, `log_rate_scaling`); LCSRS > 0 scales ECRIT too, < 0 not
RATES = "*DEFINE_CURVE\n       905\n                 0.0                 0.5\n" \
        "              1000.0                 2.0\n"
LOG_RATES = "*DEFINE_CURVE\n       906\n                -5.0                 0.5\n" \
            "                 7.0                 2.0\n"
ECRIT_CARD = "       901    -903.0       2.0       0.0       2.0       902"
ECRIT_CURVE = "*DEFINE_CURVE\n       903\n               -0.33               0.015\n" \
              "                0.67               0.004\n"
ECRIT_FADING = "{critical_strain: [[-0.33, 0.015], [0.67, 0.004]], exponent: 2"
h_lcsrs = gissmo_twin("GISSMO LCSRS", "gissmo_lcsrs", GISSMO_CARD_2 + "\n       905", RATES,
                      "{critical_damage: 0, exponent: 1}, rate_scaling: [[0, 0.5], [1000, 2]]")
check("GISSMO LCSRS: the rate's factor changes the history",
      h_lcsrs is not None and h_gissmo is not None and read(h_lcsrs) != read(h_gissmo))
gissmo_twin("GISSMO LCSRS of logarithms", "gissmo_lcsrs_log", GISSMO_CARD_2 + "\n       906", LOG_RATES,
            "{critical_damage: 0, exponent: 1}, log_rate_scaling: [[-5, 0.5], [7, 2]]")
h_ecrit_scaled = gissmo_twin(
    "GISSMO LCSRS > 0 with ECRIT", "gissmo_lcsrs_ecrit", ECRIT_CARD + "\n       905", ECRIT_CURVE + RATES,
    ECRIT_FADING + "}, rate_scaling: [[0, 0.5], [1000, 2]]")
h_ecrit_kept = gissmo_twin(
    "GISSMO LCSRS < 0 with ECRIT", "gissmo_lcsrs_ecrit_kept", ECRIT_CARD + "\n      -905", ECRIT_CURVE + RATES,
    ECRIT_FADING + ", rate_scaled: false}, rate_scaling: [[0, 0.5], [1000, 2]]")
check("GISSMO LCSRS: its sign says whether it scales ECRIT (two histories)",
      h_ecrit_scaled is not None and h_ecrit_kept is not None and read(h_ecrit_scaled) != read(h_ecrit_kept))
for name, gissmo, message in (
        ("LCSDG not a curve", GISSMO.replace("       901       0.0", "       777       0.0"),
         "no *DEFINE_CURVE defines it"),
        ("another driving variable", GISSMO.replace("         1                 1",
                                                    "         1                11"), "DTYP 11"),
        ("DCRIT 1", GISSMO.replace("       2.0       0.0       1.0", "       2.0       1.0       1.0"),
         "DCRIT must be in [0, 1)")):
    folder = write_case("gissmo_bad", strip_deck.replace("*END\n", gissmo + "*END\n"),
                        os.path.join(STRIP, "strip_pull_mesh.k"))
    r = subprocess.run([FPM, "check", os.path.join(folder, "model.k")], capture_output=True,
                       text=True)
    check(f"GISSMO: {name} refused with exit 2 and one sentence",
          r.returncode == 2 and r.stderr.count("error:") == 1 and message in r.stderr, r.stderr)

# ---- *MAT_ADD_EROSION (theory.md eq. 7.6-5): strip_pull.k's steel eroding at an effective strain
# of 2 % (EFFEPS, NUMFIP 1), against the twin with failure: {thresholds}; its GISSMO of R10 and
# before (IDAM 1, card 3) gives the bytes of *MAT_ADD_DAMAGE_GISSMO's; refusals
EROSION = """*MAT_ADD_EROSION
$#     mid      excl    mxpres     mneps    effeps    voleps    numfip       ncs
         1       0.0       0.0       0.0      0.02       0.0       1.0       1.0
$#  mnpres     sigp1     sigvm     mxeps     epssh     sigth   impulse    failtm
       0.0       0.0       0.0       0.0       0.0       0.0       0.0       0.0
"""
h_erosion = deck_against_twin(
    "MAT_ADD_EROSION", os.path.join(WORK, "add_erosion"), os.path.join(STRIP, "strip_pull_mesh.k"),
    strip_deck.replace("*END\n", EROSION + "*END\n"),
    strip_twin.replace("    poisson_ratio: 0.3\n    flow_curves:",
                       "    poisson_ratio: 0.3\n    failure: {thresholds: {max_effective_strain: 0.02}, "
                       "points: 1}\n    flow_curves:"))
check_erodes("MAT_ADD_EROSION: the strip's elements erode", h_erosion)
# NUMFIP < 0: a percentage of the layers through the thickness (of shells), as layer_fraction
h_layers = deck_against_twin(
    "MAT_ADD_EROSION NUMFIP < 0", os.path.join(WORK, "add_erosion_layers"), os.path.join(STRIP, "strip_pull_mesh.k"),
    strip_deck.replace("*END\n", EROSION.replace("      0.02       0.0       1.0", "      0.02       0.0     -50.0") + "*END\n"),
    strip_twin.replace("    poisson_ratio: 0.3\n    flow_curves:",
                       "    poisson_ratio: 0.3\n    failure: {thresholds: {max_effective_strain: 0.02}, "
                       "layer_fraction: 0.5}\n    flow_curves:"))
check_erodes("MAT_ADD_EROSION NUMFIP < 0: the strip's elements erode", h_layers)
# card 4's EPSTHIN (each point's thinning) as thinning_strain; card 5's DTMIN as the material's
# minimum_time_step (its steps fall from 5.87e-7 to 5.82e-7 as the strip is drawn)
NO_EFFEPS = EROSION.replace("      0.02       0.0       1.0", "       0.0       0.0       1.0")
CARD_3 = "$#    idam\n         0\n"
for name, cards, twin_failure in (
        ("EPSTHIN", CARD_3 + "$#   lcfld      nsff   epsthin\n         0        10     0.004\n",
         "{thresholds: {thinning_strain: 0.004}, points: 1}"),
        ("DTMIN", CARD_3 + "         0        10       0.0\n$#  dteflt   volfrac     mxtmp     dtmin\n"
                  "       0.0       0.0       0.0   5.85e-7\n", "{minimum_time_step: 5.85e-7}")):
    h_card = deck_against_twin(
        "MAT_ADD_EROSION " + name, os.path.join(WORK, "add_erosion_" + name.lower()),
        os.path.join(STRIP, "strip_pull_mesh.k"),
        strip_deck.replace("*END\n", NO_EFFEPS + cards + "*END\n"),
        strip_twin.replace("    poisson_ratio: 0.3\n    flow_curves:",
                           "    poisson_ratio: 0.3\n    failure: " + twin_failure + "\n    flow_curves:"))
    check_erodes("MAT_ADD_EROSION " + name + ": the strip's elements erode", h_card)



IDAM = EROSION.replace("      0.02", "       0.0") + (
    "$#    idam    dmgtyp     lcsdg     ecrit    dmgexp     dcrit    fadexp    lcregd\n"
    "         1         0       901       0.0       2.0       0.0       1.0       902\n")
gissmo_curves = GISSMO[GISSMO.index("*DEFINE_CURVE"):]
STRIP_MESH = os.path.join(STRIP, "strip_pull_mesh.k")
r_idam, h_idam = run(os.path.join(write_case("add_erosion_idam", strip_deck.replace(
    "*END\n", IDAM + gissmo_curves + "*END\n"), STRIP_MESH), "model.k"),
    os.path.join(WORK, "add_erosion_idam", "out"))
check("MAT_ADD_EROSION IDAM 1: the history of *MAT_ADD_DAMAGE_GISSMO's, byte for byte",
      r_idam.returncode == 0 and h_gissmo is not None and read(h_idam) == read(h_gissmo), r_idam.stderr)
for name, card, message in (
        ("Tuler-Butcher", EROSION.replace("       0.0       0.0       0.0\n", "     1.0e8       0.0       0.0\n"),
         "SIGTH: the Tuler-Butcher criterion is not supported"),
        ("a forming limit", EROSION + "         0         0         0\n" + "       901\n",
         "forming limits"),
        ("IDAM 2", EROSION + "         2\n", "IDAM 2 is not supported"),
        ("EPSTHIN < 0", EROSION + "         0\n         0        10    -0.004\n", "EPSTHIN < 0"),
        ("DTMIN < 0", EROSION + "         0\n         0        10       0.0\n       0.0       0.0       0.0    -1e-7\n",
         "DTMIN < 0 is not supported"),
        ("NUMFIP below -100", EROSION.replace("      0.02       0.0       1.0", "      0.02       0.0    -150.0"),
         "NUMFIP must be at least -100"),
        ("SIGP1 a curve", EROSION.replace("       0.0       0.0       0.0       0.0       0.0       0.0       0.0       0.0\n",
                                          "       0.0    -901.0       0.0       0.0       0.0       0.0       0.0       0.0\n"),
         "SIGP1 < 0")):
    folder = write_case("add_erosion_bad", strip_deck.replace("*END\n", card + gissmo_curves + "*END\n"),
                        STRIP_MESH)
    r = subprocess.run([FPM, "check", os.path.join(folder, "model.k")], capture_output=True, text=True)
    check(f"MAT_ADD_EROSION: {name} refused with exit 2 and one sentence",
          r.returncode == 2 and r.stderr.count("error:") == 1 and message in r.stderr, r.stderr)

# ---- *MAT_TABULATED_JOHNSON_COOK (224): strip_pull.k's flow table as LCK1, its failure strain
# against triaxiality (LCF) times factors of the plastic strain rate (LCG) and the element size
# (LCI), against the twin's tabulated law with failure: {tabulated: {failure_strain,
# rate_scaling, regularization}} (theory.md eq. 7.6-3); NUMINT -50 as layer_fraction 0.5
MAT_224_CURVES = ("*DEFINE_CURVE\n       907\n               -0.33                0.03\n"
                  "                0.33                0.01\n                0.67               0.008\n"
                  "*DEFINE_CURVE\n       908\n                 0.0                 0.8\n"
                  "               100.0                 1.2\n"
                  "*DEFINE_CURVE\n       909\n               0.001                 1.2\n"
                  "                0.01                 0.8\n")


def mat_224(numint, lckt="0"):
    return ("*MAT_TABULATED_JOHNSON_COOK\n"
            "$#     mid        ro         e        pr        cp        tr      beta    numint\n"
            "         1    7850.0   2.1e+11       0.3     452.0     293.0       0.9%10s\n" % numint +
            "$#    lck1      lckt       lcf       lcg       lch       lci\n"
            "         5%10s       907       908         0       909\n" % lckt)


MAT_024_CARD = strip_deck[strip_deck.index("*MAT_PIECEWISE_LINEAR_PLASTICITY"):strip_deck.index("*DEFINE_TABLE")]
TWIN_224 = ("    failure: {tabulated: {failure_strain: [[-0.33, 0.03], [0.33, 0.01], [0.67, 0.008]], "
            "rate_scaling: [[0, 0.8], [100, 1.2]], regularization: [[0.001, 1.2], [0.01, 0.8]]}, %s}\n")
for name, numint, erode_key in (("MAT_224", "1.0", "points: 1"), ("MAT_224 NUMINT < 0", "-50.0", "layer_fraction: 0.5")):
    h_224 = deck_against_twin(
        name, os.path.join(WORK, name.replace(" ", "_").replace("<", "lt")), os.path.join(STRIP, "strip_pull_mesh.k"),
        strip_deck.replace(MAT_024_CARD, mat_224(numint)).replace("*END\n", MAT_224_CURVES + "*END\n"),
        strip_twin.replace("    poisson_ratio: 0.3\n    flow_curves:",
                           "    poisson_ratio: 0.3\n" + TWIN_224 % erode_key + "    flow_curves:"))
    check_erodes(name + ": the strip's elements erode", h_224)
for name, text, message in (
        ("LCKT", strip_deck.replace(MAT_024_CARD, mat_224("1.0", "11")), "LCKT (flow curves per temperature)"),
        ("LCF a table", strip_deck.replace(MAT_024_CARD, mat_224("1.0").replace("       907", "         5")),
         "LCF 5: a table")):
    folder = write_case("mat224_bad", text.replace("*END\n", MAT_224_CURVES + "*END\n"), os.path.join(STRIP, "strip_pull_mesh.k"))
    r = subprocess.run([FPM, "check", os.path.join(folder, "model.k")], capture_output=True, text=True)
    check(f"MAT_224: {name} refused with exit 2 and one sentence",
          r.returncode == 2 and r.stderr.count("error:") == 1 and message in r.stderr, r.stderr)

# ---- *MAT_PLASTICITY_WITH_DAMAGE (081): strip_pull.k's steel softened by damage from a plastic
# strain of 1 % (EPPF) to 3 % (EPPFR), eroding there (NUMINT 1), against the twin with
# type: plastic_damage (theory.md eq. 7.6-4)
MAT_024 = "*MAT_PIECEWISE_LINEAR_PLASTICITY\n" + STRIP_MAT + "$#       c         p      lcss\n       0.0       0.0         5\n"
MAT_081 = ("*MAT_PLASTICITY_WITH_DAMAGE\n"
           "$#     mid        ro         e        pr      sigy      etan      eppf      tdel\n"
           "         1    7850.0   2.1e+11       0.3   3.0e+08       0.0      0.01\n"
           "$#       c         p      lcss      lcsr     eppfr        vp      lcdm    numint\n"
           "       0.0       0.0         5         0      0.03         0         0         1\n")
assert MAT_024 in strip_deck and "    type: tabulated\n" in strip_twin
h_081 = deck_against_twin(
    "*MAT_081", os.path.join(WORK, "mat081"), os.path.join(STRIP, "strip_pull_mesh.k"),
    strip_deck.replace(MAT_024, MAT_081),
    strip_twin.replace("    type: tabulated\n", "    type: plastic_damage\n").replace(
        "    poisson_ratio: 0.3\n    flow_curves:",
        "    poisson_ratio: 0.3\n    damage: {start: 0.01, rupture: 0.03}\n"
        "    failure: {plastic_strain: 0.03, points: 1}\n    flow_curves:"))
check_erodes("*MAT_081: the strip ruptures and erodes", h_081)
# ---- friction in a *CONTACT_ card: plate_hammer.k's self-contact (the hammer on the doubler and
# the plate) with FS 0.2, FD 0.1, DC 5 (LS-DYNA's decay, theory.md eq. 8.4-5), against the twin
# with the same keys; FS < 0 refused, VC noted
HAMMER = os.path.join(DECKS, "plate_hammer")
hammer_deck = read(os.path.join(HAMMER, "plate_hammer.k"))
hammer_twin = read(os.path.join(HAMMER, "plate_hammer.yaml"))
FRICTIONLESS = "$#      fs        fd\n       0.0       0.0\n"
assert FRICTIONLESS in hammer_deck and "  - {type: self, elements: all}\n" in hammer_twin


h_frictional = deck_against_twin(
    "contact friction", os.path.join(WORK, "friction"), os.path.join(HAMMER, "plate_hammer_mesh.k"),
    hammer_deck.replace(FRICTIONLESS, "$#      fs        fd        dc\n       0.2       0.1       5.0\n"),
    hammer_twin.replace("  - {type: self, elements: all}\n",
                        "  - {type: self, elements: all, friction: 0.2, friction_dynamic: 0.1, "
                        "friction_decay: 5}\n"))
h_frictionless = os.path.join(WORK, "plate_hammer", "deck", "history.csv")
if h_frictional and os.path.exists(h_frictionless):
    check("contact friction: it changes the impact", read(h_frictional) != read(h_frictionless),
          "the same history with and without friction")


def hammer_check(name, deck_text):
    folder = write_case(name, deck_text, os.path.join(HAMMER, "plate_hammer_mesh.k"))
    return fpmshell("check", os.path.join(folder, "model.k"))


r = hammer_check("friction_table", hammer_deck.replace(FRICTIONLESS, "      -2.0\n"))
check("FS < 0 (a friction table) is refused naming the card",
      r.returncode == 2 and "*CONTACT_AUTOMATIC_SINGLE_SURFACE_ID" in r.stderr and "FS < 0" in r.stderr,
      r.stderr)
r = hammer_check("friction_vc", hammer_deck.replace(
    FRICTIONLESS, "       0.2       0.0       0.0     1.0e8\n"))
check("VC is noted as not honoured", r.returncode == 0 and "VC ignored" in r.stdout,
      r.stdout + r.stderr)

# ---- *INITIAL_VELOCITY_GENERATION with OMEGA: plate_drop.k spinning about a tilted axis
generation = drop_deck[drop_deck.index("*INITIAL_VELOCITY_GENERATION"):drop_deck.index("*RIGIDWALL_PLANAR_ID")]
spinning = ("*INITIAL_VELOCITY_GENERATION\n         1         2      20.0       0.0       0.0      -5.0\n"
            "      0.05      0.05       0.0       0.0       0.6       0.8\n")
twin_velocity = "  - {nodes: all, velocity: [0, 0, -5]}\n"
twin_spinning = ("  - {nodes: all, velocity: [0, 0, -5], rotation: {centre: [0.05, 0.05, 0],\n"
                 "     angular_velocity: [0, 12, 16]}}\n")
assert twin_velocity in drop_twin
deck_against_twin("initial rotation", os.path.join(WORK, "spin"),
                  os.path.join(DROP, "plate_drop_mesh.k"), drop_deck.replace(generation, spinning),
                  drop_twin.replace(twin_velocity, twin_spinning))

# ---- check prints the deck as understood
c = fpmshell("check", os.path.join(DECKS, "tube_crush", "tube_crush.k"))
out = c.stdout
check("check: exit 0", c.returncode == 0, c.stderr)
for expected in ("material mat_1: johnson_cook", "section 0: 384 elements, material mat_1, "
                 "thickness 0.001, 5 Gauss x 3 points", "rigid body rigidwall1", "contact self over 384",
                 "note: ", "*HOURGLASS: ignored", "192 quadrangles split", "*MAT_JOHNSON_COOK"):
    check(f"check prints '{expected}'", expected in out, out)

sys.exit(finish())

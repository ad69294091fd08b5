"""The rigid-body cards of decks (docs/decks.md; theory.md eq. 6.11-7), each a variant of
plate_hammer.k (a rigid hammer, part 3, on a welded plate) against its YAML twin, the same
history.csv bytes:

- *BOUNDARY_PRESCRIBED_MOTION_RIGID: the hammer driven down at a velocity (DOF 3, VAD 0), turned
  about x (DOF 5), pushed by an acceleration (VAD 1), lowered by a displacement (VAD 2) -> `boundary` entries of type rigid_body;
- *CONSTRAINED_EXTRA_NODES_NODE / _SET and *CONSTRAINED_RIGID_BODIES -> `constraints` entries over
  a list of node sets; *CONTACT_TIED_SURFACE_TO_SURFACE_OFFSET -> a `constraints` entry of type
  tied; *CONSTRAINED_GENERALIZED_WELD_SPOT over three nodes with SN, SS or EPSF -> groups of three
  with `failure` (theory.md eqs. 6.11-14, 6.11-15), which the hammer's blow lets go;
- *CONSTRAINED_SPOTWELD with SN, SS, TF or EP -> `failure` (eqs. 6.11-13, 6.11-15);
- refusals with exit 2 and one sentence naming the place: VAD 1, DOF 4 with a vector, a
  rotation given as an angle, a part that is not rigid; the YAML keys' errors.

usage: deck_rigid_test.py FPMSHELL WORKDIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_variant  # noqa: E402
from deck_variant import fpmshell, read, run, twin_pair  # noqa: E402

WORK, HAMMER, deck, twin, write = deck_variant.start(sys.argv, "plate_hammer")
END = "*END\n"
assert deck.endswith(END) and "\noutput:" in twin and "\nboundary:" not in twin
# the hammer (initial velocity -10 m/s) driven on at -10 m/s and sent back up at 5 m/s from 0.7 ms,
# just before it would meet the plate at 0.8 ms (a drive through the plate would crush it against
# the floor it lies on: the unit tests drive a body into a strip); a displacement of -10 m/s x t
# that turns back the same way
CURVE = ("*DEFINE_CURVE\n$#    lcid      sidr       sfa       sfo\n         9\n"
         "$#                a1                  o1\n                 0.0                 1.0\n"
         "              0.0006                 1.0\n              0.0007                -0.5\n"
         "                 1.0                -0.5\n"
         "*DEFINE_CURVE\n        10\n                 0.0                 0.0\n"
         "              0.0007                 1.0\n               0.002                0.05\n"
         "*DEFINE_CURVE\n        11\n                 0.0                 1.0\n"
         "                 1.0                 1.0\n")
TWIN_CURVE = ("curves:\n  curve_9: [[0, 1], [0.0006, 1], [0.0007, -0.5], [1, -0.5]]\n"
              "  curve_10: [[0, 0], [0.0007, 1], [0.002, 0.05]]\n  curve_11: [[0, 1], [1, 1]]\n")

VARIANTS = {  # name: (cards added to the deck, the twin's boundary entries)
    "velocity": ("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n$#     pid       dof       vad      lcid"
                 "        sf\n         3         3         0         9     -10.0\n",
                 "  - {rigid_body: part_3, prescribe: {velocity: [0, 0, -10], curve: curve_9, "
                 "components: [uz]}}\n"),
    "velocity and rotation (_ID, two records)": (
        "*BOUNDARY_PRESCRIBED_MOTION_RIGID_ID\n         1hammer drive\n"
        "         3         3         0         9     -10.0\n"
        "         3         5         0         9      20.0\n",
        "  - {rigid_body: part_3, prescribe: {velocity: [0, 0, -10], curve: curve_9, "
        "components: [uz]}}\n"
        "  - {rigid_body: part_3, prescribe: {angular_velocity: [20, 0, 0], curve: curve_9, "
        "components: [rx]}}\n"),
    # thrown down at 10 m/s and braked at 15 000 m/s^2: it stops 3.3 mm lower at 0.67 ms, short
    # of the doubler, and goes back up
    "acceleration": ("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         3         3         1        11"
                     "   15000.0\n",
                     "  - {rigid_body: part_3, prescribe: {acceleration: [0, 0, 15000], curve: curve_11, "
                     "components: [uz]}}\n"),
    "displacement": ("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         3         3         2        10"
                     "    -0.007\n",
                     "  - {rigid_body: part_3, prescribe: {displacement: [0, 0, -0.007], "
                     "curve: curve_10, components: [uz]}}\n"),
}
histories = {}
for k, (name, (cards, entries)) in enumerate(VARIANTS.items()):
    folder = os.path.join(WORK, f"motion{k}")
    d = write(folder, "model.k", deck[:-len(END)] + CURVE + cards + END)
    t = write(folder, "model.yaml", twin.replace("\noutput:", "\n" + TWIN_CURVE + "\nboundary:\n" +
                                                 entries + "\noutput:"))
    history = twin_pair(name, d, t)
    if history is not None:
        histories[name] = history
# *CONSTRAINED_EXTRA_NODES (_NODE, _SET) and *CONSTRAINED_RIGID_BODIES: `constraints` entries over
# the union of node sets. The plate's nodes 41 and 42 ride with the hammer; the doubler (part 2),
# made rigid (*MAT_RIGID 3) and unwelded, joins the hammer, both thrown up at 5 m/s (joined at
# different velocities, the merge would be an inelastic collision at t = 0)
WELDS = deck[deck.index("*CONSTRAINED_SPOTWELD"):deck.index("*INITIAL_VELOCITY_GENERATION")]
THROW = ("*INITIAL_VELOCITY_GENERATION\n$#      id      styp     omega        vx        vy        vz\n"
         "         3         2       0.0       0.0       0.0     -10.0\n")
assert THROW in deck
RIGID_DOUBLER = (("*PART\ndoubler\n         2         1         1\n",
                  "*PART\ndoubler\n         2         1         3\n*MAT_RIGID\n         3   78500.0   "
                  "2.1e+11       0.3\n"), (WELDS, ""),
                 (THROW, THROW.replace("-10.0", "  5.0") + "         0.0       0.0       0.0       0.0"
                  "       0.0       0.0\n" + THROW.replace("-10.0", "  5.0").replace(
                      "         3         2", "         2         2").split("\n", 2)[2]))
TWIN_DOUBLER = (("  - {elements: part_2, material: steel, thickness: 0.002, thickness_points: 5, "
                 "thickness_rule: gauss}\n", "  - {elements: part_2, material: mat_3, thickness: 0.002, "
                 "thickness_points: 5, thickness_rule: gauss}\n"),
                ("\nsections:", "  mat_3: {type: rigid, density: 78500, youngs_modulus: 2.1e11, "
                 "poisson_ratio: 0.3}\n\nsections:"),
                ("  - {nodes: part_3, velocity: [0, 0, -10]}\n",
                 "  - {nodes: part_3, velocity: [0, 0, 5]}\n  - {nodes: part_2, velocity: [0, 0, 5]}\n"),
                *[(f"  - {{type: rigid, nodes: weld_{w}}}\n", "") for w in "abcd"])
assert all(a in deck for a, _ in RIGID_DOUBLER) and all(a in twin for a, _ in TWIN_DOUBLER)
CONSTRAINT_VARIANTS = {  # name: (deck edits, cards, twin sets, twin constraints, twin edits)
    "extra nodes (_NODE)": ((), "*CONSTRAINED_EXTRA_NODES_NODE\n         3        41\n         3        42\n",
                            "  extra_nodes_3: {node_ids: [41, 42]}\n",
                            "  - {type: rigid, nodes: [part_3, extra_nodes_3]}\n", ()),
    "extra nodes (_SET)": ((), "*SET_NODE_LIST\n        77\n        41        42\n"
                           "*CONSTRAINED_EXTRA_NODES_SET\n         3        77\n",
                           "  riders: {node_ids: [41, 42]}\n",
                           "  - {type: rigid, nodes: [part_3, riders]}\n", ()),
    "rigid bodies joined": (RIGID_DOUBLER, "*CONSTRAINED_RIGID_BODIES\n         3         2\n", "",
                            "  - {type: rigid, nodes: [part_3, part_2]}\n", TWIN_DOUBLER),
}
for k, (name, (edits, cards, sets, constraints, twin_edits)) in enumerate(CONSTRAINT_VARIANTS.items()):
    folder = os.path.join(WORK, f"joined{k}")
    d_text = deck
    for a, b in edits:
        d_text = d_text.replace(a, b)
    t_text = twin.replace("\nsets:\n", "\nsets:\n" + sets).replace(
        "\nconstraints:\n", "\nconstraints:\n" + constraints)
    for a, b in twin_edits:
        t_text = t_text.replace(a, b)
    d = write(folder, "model.k", d_text[:-len(END)] + cards + END)
    t = write(folder, "model.yaml", t_text)
    history = twin_pair(name, d, t)
    if history is not None:
        histories[name] = history
c = fpmshell("check", os.path.join(WORK, "joined2", "model.k"))
check("rigid bodies joined: the hammer and the doubler one body, the plate's edge the other",
      c.returncode == 0 and "nodal rigid bodies: 2 (" in c.stdout, c.stdout + c.stderr)

# card order is free for these cards too: the drive (and its curve) first in the deck, before the
# parts and the mesh it refers to, gives the same bytes
cards = VARIANTS["velocity"][0]
early = write(os.path.join(WORK, "velocity_first"), "model.k",
              deck.replace("*KEYWORD\n", "*KEYWORD\n" + cards + CURVE, 1))
r_early, h_early = run(early)
check("velocity: the drive first in the deck, the same history.csv",
      r_early.returncode == 0 and "velocity" in histories and read(h_early) == histories["velocity"],
      r_early.stderr)

r_free, h_free = run(write(os.path.join(WORK, "free"), "model.k", deck))
if r_free.returncode == 0:
    histories["free"] = read(h_free)
# the two forms of the extra nodes are the same model; every other variant is a run of its own
check("extra nodes: _NODE and _SET give the same bytes",
      histories.get("extra nodes (_NODE)") == histories.get("extra nodes (_SET)") is not None,
      "they differ")
histories.pop("extra nodes (_SET)", None)
check("the drives and joins change the run (each history differs)",
      len(set(histories.values())) == len(histories) == len(VARIANTS) + len(CONSTRAINT_VARIANTS),
      f"{len(set(histories.values()))} distinct of {len(histories)}")

# under the acceleration drive (15 000 m/s^2 from -10 m/s): the hammer's acceleration is the
# drive's at every sample (to rounding), and its velocity v^{n-1/2} = -10 + 15000 (t - dt/2): within
# 15000 dt / 2 = 0.011 m/s of -10 + 15000 t (dt = 1.47 us)
rows = [line.split(",") for line in histories.get("acceleration", "").splitlines()]
if rows and "node205_az" in rows[0]:
    k, ka = rows[0].index("node205_vz"), rows[0].index("node205_az")
    ramp = [(float(r[0]), float(r[k]), float(r[ka])) for r in rows[2:]]
    check("acceleration: the hammer's acceleration is 15000 m/s^2",
          ramp and all(abs(a - 15000) < 1e-6 for _, _, a in ramp), ramp[-3:])
    check("acceleration: the hammer's velocity is -10 + 15000 t",
          ramp and all(0 < (-10 + 15000 * t) - v < 0.012 for t, v, _ in ramp), ramp[-3:])
else:
    check("acceleration: the history has node205_vz", False, rows[:1])

# the hammer's centre (node 205) under the velocity drive: z velocity -10 once the ramp is done
rows = [line.split(",") for line in histories.get("velocity", "").splitlines()]
if rows:
    header = rows[0]
    if "node205_vz" in header:
        k = header.index("node205_vz")
        before = [float(r[k]) for r in rows[1:] if float(r[0]) < 0.0006]
        after = [float(r[k]) for r in rows[1:] if float(r[0]) > 0.0007]
        check("velocity: the hammer moves at -10 m/s, then back up at 5 m/s",
              before and after and all(abs(v + 10) < 1e-6 for v in before) and
              all(abs(v - 5) < 1e-6 for v in after), (before[-3:], after[:3]))
    else:
        check("velocity: the history has node205_vz", False, header)


def refused(name, cards, *words):
    path = write(os.path.join(WORK, name.replace(" ", "_")), "model.k",
                 deck[:-len(END)] + CURVE + cards + END)
    r = fpmshell("check", path)
    check(f"{name}: exit 2, one sentence naming the place",
          r.returncode == 2 and all(w in r.stderr for w in words) and
          len(r.stderr.strip().splitlines()) == 1, r.stderr)


refused("angular acceleration", "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         3         5         1"
        "         9\n", "model.k:", "*BOUNDARY_PRESCRIBED_MOTION_RIGID", "VAD 1")
refused("vector", "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         3         4         0         9"
        "       1.0         7\n", "model.k:", "DOF 4")
refused("angle", "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         3         6         2         9\n",
        "model.k:", "VAD 2", "angular velocity")
refused("not rigid", "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         1         3         0         9\n",
        "model.k:", "*BOUNDARY_PRESCRIBED_MOTION_RIGID", "not of a rigid material")
refused("extra nodes of a deformable part", "*CONSTRAINED_EXTRA_NODES_NODE\n         1        41\n",
        "model.k:", "*CONSTRAINED_EXTRA_NODES_NODE", "PID 1: the part is not of *MAT_RIGID")
refused("joined with a deformable part", "*CONSTRAINED_RIGID_BODIES\n         3         1\n",
        "model.k:", "*CONSTRAINED_RIGID_BODIES", "PIDC 1: the part is not of *MAT_RIGID")

# *INITIAL_VELOCITY_RIGID_BODY: the hammer thrown by it instead of _GENERATION is the same model:
# the same history bytes as the deck as it is
THROW_CARDS = THROW + "       0.0       0.0       0.0       0.0       0.0       0.0\n"
assert THROW_CARDS in deck
by_body = write(os.path.join(WORK, "rigid_body_velocity"), "model.k", deck.replace(
    THROW_CARDS, "*INITIAL_VELOCITY_RIGID_BODY\n$#     pid        vx        vy        vz\n"
    "         3       0.0       0.0     -10.0\n"))
r_body, h_body = run(by_body)
check("*INITIAL_VELOCITY_RIGID_BODY: the history of the deck with _GENERATION, byte for byte",
      r_body.returncode == 0 and "free" in histories and read(h_body) == histories["free"],
      r_body.stderr)
# a spin VXR..VZR about the body's centre of mass: `rotation: {centre: mass, ...}` in the twin
spun = write(os.path.join(WORK, "rigid_body_spin"), "model.k", deck.replace(
    THROW_CARDS, "*INITIAL_VELOCITY_RIGID_BODY\n$#     pid        vx        vy        vz       vxr"
    "       vyr       vzr\n         3       0.0       0.0     -10.0       0.0       0.0      30.0\n"))
THROW_TWIN = "  - {nodes: part_3, velocity: [0, 0, -10]}\n"
assert THROW_TWIN in twin
spun_twin = write(os.path.join(WORK, "rigid_body_spin"), "model.yaml", twin.replace(
    THROW_TWIN, "  - {nodes: part_3, velocity: [0, 0, -10], rotation: {centre: mass, "
    "angular_velocity: [0, 0, 30]}}\n"))
spin_history = twin_pair("*INITIAL_VELOCITY_RIGID_BODY with a spin about the centre of mass", spun,
                         spun_twin)
check("the spin changes the run", spin_history is not None and spin_history != histories.get("free"),
      "the same history")

# *CONTACT_TIED_SURFACE_TO_SURFACE_OFFSET: the doubler (part 2) tied to the plate (part 1) instead
# of welded, lowered to 1.5 mm above the plate (within the tie's reach, the larger thickness,
# 2 mm) -> `constraints` of type tied
mesh_text = read(os.path.join(HAMMER, "plate_hammer_mesh.k"))
lowered = "\n".join(
    line[:40] + "           0.003" + line[56:]
    if line[:8].strip().isdigit() and 101 <= int(line[:8]) <= 125 and line[40:56].strip() == "0.005"
    else line for line in mesh_text.split("\n"))
assert lowered != mesh_text
TIE = ("*CONTACT_TIED_SURFACE_TO_SURFACE_OFFSET_ID\n         5doubler on plate\n"
       "$#    ssid      msid     sstyp     mstyp\n         2         1         3         3\n\n")
folder = os.path.join(WORK, "tied")
d = write(folder, "model.k", deck.replace(WELDS, "")[:-len(END)] + TIE + END)
t = write(folder, "model.yaml", twin.replace("\nconstraints:\n", "\nconstraints:\n"
                                             "  - {type: tied, nodes: part_2, elements: part_1}\n")
          .replace("".join(f"  - {{type: rigid, nodes: weld_{w}}}\n" for w in "abcd"), ""))
with open(os.path.join(folder, "plate_hammer_mesh.k"), "w") as f:
    f.write(lowered)
history_tied = twin_pair("tied contact", d, t)
early_tie = write(os.path.join(WORK, "tied_first"), "model.k",
                  deck.replace(WELDS, "").replace("*KEYWORD\n", "*KEYWORD\n" + TIE, 1))
with open(os.path.join(WORK, "tied_first", "plate_hammer_mesh.k"), "w") as f:
    f.write(lowered)
r_early, h_early = run(early_tie)
check("tied contact: the card first in the deck, the same history.csv",
      r_early.returncode == 0 and history_tied is not None and read(h_early) == history_tied,
      r_early.stderr)
c = fpmshell("check", d)
check("tied contact: the doubler's 25 particles tied to the plate's faces",
      c.returncode == 0 and "tied: 25 particles to faces" in c.stdout and
      "keep their offset" not in c.stdout, c.stdout + c.stderr)
# *CONTACT_TIEBREAK_NODES_TO_SURFACE: the same ties letting go at a normal force of 2 N or a shear
# force of 1 N (the hammer's blow tears the doubler off) -> failure keys; the run differs from the
# plain ties'
BREAK = ("*CONTACT_TIEBREAK_NODES_TO_SURFACE_ID\n         6doubler glued\n"
         "         2         1         3         3\n\n\n$#    nflf      sflf       nen       mes\n"
         "       2.0       1.0\n")
folder = os.path.join(WORK, "tiebreak_nodes")
d = write(folder, "model.k", deck.replace(WELDS, "")[:-len(END)] + BREAK + END)
t = write(folder, "model.yaml", twin.replace(
    "\nconstraints:\n", "\nconstraints:\n  - {type: tied, nodes: part_2, elements: part_1, failure: "
    "{normal_force: 2, shear_force: 1, normal_exponent: 2, shear_exponent: 2}}\n").replace(
    "".join(f"  - {{type: rigid, nodes: weld_{w}}}\n" for w in "abcd"), ""))
with open(os.path.join(folder, "plate_hammer_mesh.k"), "w") as f:
    f.write(lowered)
history_break = twin_pair("tiebreak", d, t)
if history_break is not None:
    check("tiebreak: the ties that let go change the run", history_break != history_tied,
          "the same history as the plain ties")
# *CONTACT_TIEBREAK_SURFACE_TO_SURFACE: the same glue given as stresses, NFLS 12.8 kPa and SFLS
# 6.4 kPa: times each doubler node's area (an inner node's 12.5 mm x 12.5 mm) the nodes version's
# 2 N and 1 N -> failure {normal_stress, shear_stress} (eq. 6.12-3)
BREAK_S = ("*CONTACT_TIEBREAK_SURFACE_TO_SURFACE_ID\n         7doubler glued\n"
           "         2         1         3         3\n\n\n$#    nfls      sfls    tblcid    thkoff\n"
           "   12800.0    6400.0\n")
folder = os.path.join(WORK, "tiebreak_surfaces")
d = write(folder, "model.k", deck.replace(WELDS, "")[:-len(END)] + BREAK_S + END)
t = write(folder, "model.yaml", twin.replace(
    "\nconstraints:\n", "\nconstraints:\n  - {type: tied, nodes: part_2, elements: part_1, failure: "
    "{normal_stress: 12800, shear_stress: 6400}}\n").replace(
    "".join(f"  - {{type: rigid, nodes: weld_{w}}}\n" for w in "abcd"), ""))
with open(os.path.join(folder, "plate_hammer_mesh.k"), "w") as f:
    f.write(lowered)
history_break_s = twin_pair("tiebreak by stresses", d, t)
if history_break_s is not None:
    check("tiebreak by stresses: the ties that let go change the run",
          history_break_s != history_tied, "the same history as the plain ties")
r = fpmshell("check", write(os.path.join(WORK, "tiebreak_table"), "model.k",
                            deck[:-len(END)] + BREAK_S.replace("    6400.0\n", "    6400.0         3\n") + END))
check("a tiebreak's table of stresses is refused with one sentence", r.returncode == 2 and
      "*CONTACT_TIEBREAK_SURFACE_TO_SURFACE_ID" in r.stderr and "TBLCID" in r.stderr and
      len(r.stderr.strip().splitlines()) == 1, r.stderr)

# *RIGIDWALL_PLANAR NSIDEX: the floor acts on every node but those of the plate's edge (node set
# 1, `edge`) -> the rigid contact's except_nodes
WALL_NSID = "$#    nsid\n         0\n"
assert WALL_NSID in deck
folder = os.path.join(WORK, "nsidex")
d = write(folder, "model.k", deck.replace(WALL_NSID, "$#    nsid    nsidex\n         0         1\n"))
t = write(folder, "model.yaml", twin.replace("  - {type: rigid, body: floor, offset: 0, friction: 0.2}",
                                            "  - {type: rigid, body: floor, offset: 0, friction: 0.2, "
                                            "except_nodes: edge}"))
twin_pair("NSIDEX", d, t)
c_all, c_except = fpmshell("check", os.path.join(HAMMER, "plate_hammer.k")), fpmshell("check", d)
count = lambda out: int(out.split("contact of ")[1].split(" particles")[0]) if "contact of " in out else -1
check("NSIDEX: the floor acts on the particles of the deck but the edge's",
      count(c_except.stdout) > 0 and count(c_all.stdout) - count(c_except.stdout) == 9,
      (count(c_all.stdout), count(c_except.stdout)))

# nodes that start behind a wall: LS-DYNA releases them from it; fpmshell leaves them out of the
# wall's contact with a note (initially_inside: release), where a YAML model without the key is an
# error that names the key. The floor raised to z = 2 mm, 0.5 mm above the plate.
FLOOR = "       0.0       0.0       0.0       0.0       0.0       1.0       0.2\n"
assert FLOOR in deck
raised = write(os.path.join(WORK, "behind"), "model.k",
               deck.replace(FLOOR, "       0.0       0.0     0.002       0.0       0.0     1.002       0.2\n"))
r = fpmshell("check", raised)
check("nodes behind a wall are released from it with a note", r.returncode == 0 and
      "start inside its face" in r.stdout and "left out of this contact" in r.stdout, r.stdout + r.stderr)
yaml_behind = write(os.path.join(WORK, "behind"), "model.yaml", twin.replace(
    "point: [0, 0, 0], normal: [0, 0, 1], fixed: true", "point: [0, 0, 0.002], normal: [0, 0, 1], fixed: true"))
r = fpmshell("check", yaml_behind)
check("a YAML model: particles inside a rigid face are an error naming initially_inside",
      r.returncode == 2 and "initially_inside: release" in r.stderr and "model.yaml:" in r.stderr, r.stderr)

# the YAML keys: exactly one of nodes and rigid_body; rotation axes only for a rigid body
for name, entry, words in (
        ("yaml both", "  - {nodes: part_3, rigid_body: part_3, fix: all}\n",
         ("model.yaml:", "boundary.0", "exactly one of nodes")),
        ("yaml axes on nodes", "  - {nodes: part_1, prescribe: {angular_velocity: [1, 0, 0], "
         "components: [rx]}}\n", ("model.yaml:", "boundary.0.prescribe.components",
                                  "a rigid_body's rotation axes")),
        ("yaml particles of a rigid part", "  - {nodes: part_3, fix: all}\n",
         ("model.yaml:", "boundary.0.nodes", "give the body's motion with rigid_body")),
        ("yaml two drives of one component",
         "  - {rigid_body: part_3, prescribe: {velocity: [0, 0, 1], components: [uz]}}\n"
         "  - {rigid_body: part_3, fix: [uz]}\n", ("already held or prescribed",))):
    path = write(os.path.join(WORK, name.replace(" ", "_")), "model.yaml",
                 twin.replace("\noutput:", "\nboundary:\n" + entry + "\noutput:"))
    r = fpmshell("run", path, "-o", os.path.join(WORK, name.replace(" ", "_"), "out"), "--quiet")
    check(f"{name}: exit 2 with one sentence", r.returncode == 2 and
          all(w in r.stderr for w in words) and len(r.stderr.strip().splitlines()) == 1, r.stderr)

# *CONSTRAINED_SPOTWELD's failure (theory.md eqs. 6.11-13, 6.11-15): the doubler's four welds given
# SN, SS (N, M), TF or EP, against the twin's `failure` keys: the same history.csv bytes. Forces
# and plastic strains the hammer's blow reaches let the welds go (summary.json counts them);
# forces out of reach change no byte of the welds that never fail; a failure time lets all four
# go at once.
weld_cards = deck[deck.index("*CONSTRAINED_SPOTWELD"):deck.index("*INITIAL_VELOCITY_GENERATION")]
weld_lines = [ln for ln in weld_cards.splitlines()[1:] if not ln.startswith("$")]
assert len(weld_lines) == 4
plain_history = None
for name, fields, keys, fail in (
        ("welds that fail", "     200.0     100.0       2.0       2.0",
         "normal_force: 200, shear_force: 100, normal_exponent: 2, shear_exponent: 2", True),
        ("welds out of reach", "     1e+09     1e+09", "normal_force: 1e9, shear_force: 1e9", False),
        ("welds with a failure time", "       0.0       0.0       0.0       0.0    0.0005",
         "time: 0.0005", True),
        # EP (eq. 6.11-15): the blow yields the plate around the welds to ~1e-3 and more
        ("welds that tear out", "       0.0       0.0       0.0       0.0       0.0     0.001",
         "plastic_strain: 0.001", True),
        ("welds that never tear out", "       0.0       0.0       0.0       0.0       0.0     100.0",
         "plastic_strain: 100", False)):
    folder = os.path.join(WORK, name.replace(" ", "_"))
    cards = "*CONSTRAINED_SPOTWELD\n" + "".join(f"{ln[:20]}{fields}\n" for ln in weld_lines)
    d = write(folder, "model.k", deck.replace(weld_cards, cards))
    t_text = twin
    for w in "abcd":
        t_text = t_text.replace(f"  - {{type: rigid, nodes: weld_{w}}}\n",
                                f"  - {{type: rigid, nodes: weld_{w}, failure: {{{keys}}}}}\n")
    t = write(folder, "model.yaml", t_text)
    history = twin_pair(name, d, t)
    summary = read(os.path.join(folder, "out_k", "summary.json"))
    failed = summary.split('"failed_welds":')[1].split(",")[0].strip() if '"failed_welds"' in summary else "?"
    check(f"{name}: summary.json counts the failed welds", failed != "?" and
          ((int(failed) > 0) if fail else (int(failed) == 0)), f"failed_welds {failed}")
    if name == "welds with a failure time":
        first = float(summary.split('"first_weld_failure_time":')[1].split(",")[0]) \
            if '"first_weld_failure_time"' in summary else -1
        # in the first step that ends at or after TF (the steps here are under 1 us)
        check(f"{name}: all four let go at 0.5 ms", failed == "4" and 5e-4 <= first < 5.01e-4, summary)
    if name == "welds out of reach":
        r_plain, h_plain = run(write(os.path.join(WORK, "welds_plain"), "model.k", deck))
        check("welds out of reach: the history of welds without failure data, byte for byte",
              r_plain.returncode == 0 and history is not None and read(h_plain) == history, r_plain.stderr)
# *CONSTRAINED_GENERALIZED_WELD_SPOT over three nodes each (the doubler's weld particle and its
# neighbour, the plate's particle below; theory.md eq. 6.11-14) with SN, SS, and with EPSF alone
# (eq. 6.11-15), against the twin's groups of three with `failure`: the same history.csv bytes,
# and the hammer's blow lets them go.
TRIPLES = {"a": (101, 102, 21), "b": (105, 104, 25), "c": (121, 122, 57), "d": (125, 124, 61)}
for name, fields, keys in (
        ("generalized welds of three nodes", "   1.0e+20       0.0     200.0     100.0       2.0       2.0",
         "normal_force: 200, shear_force: 100, normal_exponent: 2, shear_exponent: 2"),
        ("generalized welds that tear out", "   1.0e+20     0.001", "plastic_strain: 0.001")):
    general = "".join(
        "*SET_NODE_LIST\n%10d\n%10d%10d%10d\n*CONSTRAINED_GENERALIZED_WELD_SPOT\n%10d\n"
        "%s\n" % ((900 + k,) + t + (900 + k, fields)) for k, t in enumerate(TRIPLES.values()))
    t_text = twin
    for w, t in TRIPLES.items():
        t_text = t_text.replace("  weld_%s: {node_ids: [%d, %d]}\n" % (w, t[0], t[2]),
                                "  weld_%s: {node_ids: [%d, %d, %d]}\n" % ((w,) + t))
        t_text = t_text.replace("  - {type: rigid, nodes: weld_%s}\n" % w,
                                "  - {type: rigid, nodes: weld_%s, failure: {%s}}\n" % (w, keys))
    assert t_text.count("failure:") == 4 and "102, 21]" in t_text
    folder = os.path.join(WORK, name.replace(" ", "_"))
    history = twin_pair(name, write(folder, "model.k", deck.replace(weld_cards, general)),
                        write(folder, "model.yaml", t_text))
    summary = read(os.path.join(folder, "out_k", "summary.json"))
    check(f"{name}: the hammer's blow lets them go (summary.json)",
          '"failed_welds": 4' in summary, summary[-600:])
refused("weld with a negative EP", "*CONSTRAINED_SPOTWELD\n        41        42       0.0       0.0"
        "       0.0       0.0       0.0      -1.0\n", "model.k:", "*CONSTRAINED_SPOTWELD", "EP must be >= 0")
refused("weld with a temperature curve", "*CONSTRAINED_SPOTWELD\n        41        42     -12.0\n",
        "model.k:", "*CONSTRAINED_SPOTWELD", "SN or SS < 0")

sys.exit(finish())

"""Rigid parts of solids and given inertias in decks (docs/decks.md; theory.md §6.11),
variants of examples/decks/block_drop against YAML twins, the same history.csv bytes:

- *PART_INERTIA for the block of solids: its TM, XC..ZC, IXX..IZZ as the section's `inertia`
  (instead of the solid's), its VTX..VRZ as the body's initial velocity and spin about the centre
  (they replace those *INITIAL_VELOCITY_NODE gives its nodes);
- the deck's solids written with their nodes on a second card everywhere (LS-DYNA's two-card
  form) is the same model;
- refusals with exit 2 and one sentence naming the place: *PART_INERTIA of a deformable part,
  IRCS 1, NODEID, TM 0;
- *PART_MOVE: the block lifted before the run -> `moves`, against its twin; CID refused;
- *CONTACT_ERODING_SINGLE_SURFACE and _NODES_TO_SURFACE (of the block's part, and of a node set
  of its nodes: one-way): the block thrown through the plate that fails, as the self-contact of
  the twin; its fourth card checked.

usage: deck_solid_test.py FPMSHELL WORKDIR
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_variant  # noqa: E402
from deck_variant import fpmshell, read, run, twin_pair  # noqa: E402

WORK, BLOCK, deck, twin, write = deck_variant.start(sys.argv, "block_drop")
MESH = os.path.join(BLOCK, "block_drop_mesh.k")
PART = "*PART\nblock\n         2         2         2\n"
VELOCITY = deck[deck.index("*INITIAL_VELOCITY_NODE"):deck.index("*CONTROL_TERMINATION")]
TWIN_SECTION = "  - {elements: part_2, material: block, thickness: 0, inertia: enclosed}\n"
TWIN_VELOCITY = "  - {nodes: block_nodes, velocity: [0, 0, -5]}\n"
assert PART in deck and TWIN_SECTION in twin and TWIN_VELOCITY in twin

# a heavier block (1.2 kg, its centre 2 mm off the middle, products of inertia), thrown down at
# 5 m/s and spun at 40 rad/s about z and 10 about x
INERTIA = ("*PART_INERTIA\nblock\n         2         2         2\n"
           "$#      xc        yc        zc        tm      ircs    nodeid\n"
           "     0.052     0.049     0.022       1.2         0         0\n"
           "$#     ixx       ixy       ixz       iyy       iyz       izz\n"
           "   3.2e-04   1.0e-05  -2.0e-05   3.0e-04   5.0e-06   2.8e-04\n"
           "$#     vtx       vty       vtz       vrx       vry       vrz\n"
           "       0.0       0.0      -5.0      10.0       0.0      40.0\n")
TWIN_INERTIA = ("  - {elements: part_2, material: block, thickness: 0, inertia: {mass: 1.2, "
                "centre: [0.052, 0.049, 0.022], tensor: [3.2e-04, 1.0e-05, -2.0e-05, 3.0e-04, "
                "5.0e-06, 2.8e-04]}}\n")
TWIN_THROW = ("  - {nodes: part_2, velocity: [0, 0, -5], rotation: {centre: [0.052, 0.049, 0.022], "
              "angular_velocity: [10, 0, 40]}}\n")
d = write(os.path.join(WORK, "inertia"), "model.k", deck.replace(PART, INERTIA))
t = write(os.path.join(WORK, "inertia"), "model.yaml",
          twin.replace(TWIN_SECTION, TWIN_INERTIA).replace(TWIN_VELOCITY, TWIN_VELOCITY + TWIN_THROW))
given = twin_pair("*PART_INERTIA: the given body and its velocity", d, t)
r_as_is, h_as_is = run(write(os.path.join(WORK, "as_is"), "model.k", deck))
check("*PART_INERTIA changes the run", r_as_is.returncode == 0 and given is not None and
      read(h_as_is) != given, r_as_is.stderr)
c = fpmshell("check", d)
check("*PART_INERTIA: the total mass is the plate's and the given body's",
      c.returncode == 0 and "total mass 1.357" in c.stdout, c.stdout + c.stderr)

# the two-card form of *ELEMENT_SOLID: EID and PID alone, then the nodes
mesh = read(MESH)
head, rest = mesh.split("*ELEMENT_SOLID\n", 1)
body, tail = rest.split("*SET_NODE_LIST", 1)
cards, nodes_next = [], False
for line in body.splitlines():
    if not nodes_next and len(line) > 16 and line[16:].strip():
        cards += [line[:16], line[16:]]
    else:  # a heading of the two-card form already, or the nodes after one
        cards.append(line)
        nodes_next = not nodes_next and bool(line.strip())
two_card = head + "*ELEMENT_SOLID\n" + "\n".join(cards) + "\n*SET_NODE_LIST" + tail
folder = deck_variant.write_files(os.path.join(WORK, "two_card"),
                                  {"block_drop_mesh.k": two_card, "model.k": deck})
r_two, h_two = run(os.path.join(folder, "model.k"))
check("the two-card form of every solid: the same history.csv",
      r_two.returncode == 0 and r_as_is.returncode == 0 and read(h_two) == read(h_as_is),
      r_two.stderr)


def refused(name, text, *words):
    path = write(os.path.join(WORK, name.replace(" ", "_")), "model.k", text)
    r = fpmshell("check", path)
    check(f"{name}: exit 2, one sentence naming the place",
          r.returncode == 2 and all(w in r.stderr for w in words) and
          len(r.stderr.strip().splitlines()) == 1, r.stderr)


# *PART_MOVE: the block lifted 5 mm before the run (after the cards that refer to it: order is
# free) -> `moves`; the same as the twin that moves it, and a later impact than the deck's
MOVE = "*PART_MOVE\n$#   pid            xmov            ymov            zmov     cid   ifset\n" \
       "       2             0.0             0.0           0.005       0       0\n"
d = write(os.path.join(WORK, "moved"), "model.k", deck.replace("*END", MOVE + "*END"))
t = write(os.path.join(WORK, "moved"), "model.yaml",
          twin.replace("\nmaterials:", "\nmoves:\n  - {nodes: part_2, by: [0, 0, 0.005]}\n\nmaterials:"))
moved = twin_pair("*PART_MOVE: the block lifted before the run", d, t)
rows = [line.split(",") for line in (moved or "").splitlines()]
if rows and "node205_uz" in rows[0]:
    k = rows[0].index("node205_uz")
    # 5 mm higher, the block falls 5.5 mm before it meets the plate's surface (at 1.1 ms), not
    # 0.5 mm (at 0.1 ms)
    early = [float(r[k]) for r in rows[1:] if float(r[0]) <= 1.0e-3]
    check("*PART_MOVE: the lifted block falls freely for 1 ms",
          early and all(abs(u + 5 * float(r[0])) < 1e-9 for u, r in zip(early, rows[1:])),
          early[-3:])
refused("a move in local axes", deck.replace("*END", MOVE.replace("       0       0\n",
                                                                     "       3       0\n") + "*END"),
        "model.k:", "*PART_MOVE", "CID")


# *CONTACT_ERODING_SINGLE_SURFACE (its fourth card ISYM, EROSOP, IADJ) with the plate failing at
# a plastic strain of 0.1 (*MAT_PLASTIC_KINEMATIC FS) and the block thrown at 50 m/s: the block
# perforates the plate, whose eroded faces leave the contact (theory.md §7.6); the same bytes as
# the twin with `failure: {plastic_strain: 0.1}` and its self-contact; the two-sided eroding form
# (the block's nodes against the plate) as the self-contact over both parts
CONTACT = deck[deck.index("*CONTACT_AUTOMATIC_SINGLE_SURFACE"):deck.index("*BOUNDARY_SPC_SET")]
ERODING = CONTACT.replace("*CONTACT_AUTOMATIC_SINGLE_SURFACE", "*CONTACT_ERODING_SINGLE_SURFACE") + (
    "$#    sfsa      sfsb      sast      sbst\n       1.0       1.0\n"
    "$#    isym    erosop      iadj\n         0         1         0\n")
MAT_003 = "         1    7850.0   2.1e+11       0.3   2.5e+08   1.0e+09       1.0\n"
FAILING = MAT_003 + "$#     src       srp        fs\n       0.0       0.0       0.1\n"
TWIN_STEEL = "hardening_mix: 1}"
assert CONTACT in deck and MAT_003 in deck and TWIN_STEEL in twin
fast = deck.replace("      -5.0\n", "     -50.0\n").replace(MAT_003, FAILING)
fast_twin = twin.replace(TWIN_STEEL, "hardening_mix: 1,\n          failure: {plastic_strain: 0.1}}").replace(
    "velocity: [0, 0, -5]", "velocity: [0, 0, -50]")
d = write(os.path.join(WORK, "eroding"), "model.k", fast.replace(CONTACT, ERODING))
t = write(os.path.join(WORK, "eroding"), "model.yaml", fast_twin)
perforated = twin_pair("*CONTACT_ERODING_SINGLE_SURFACE: the block through the failing plate", d, t)
summary = os.path.join(WORK, "eroding", "out_k", "summary.json")
eroded = json.load(open(summary)).get("eroded_elements", 0) if os.path.exists(summary) else 0
check("*CONTACT_ERODING_SINGLE_SURFACE: the plate's elements under the block erode", eroded > 20, eroded)
c = fpmshell("check", d)
check("*CONTACT_ERODING_SINGLE_SURFACE: a note on the eroding contact",
      c.returncode == 0 and "an eroding contact" in c.stdout, c.stdout + c.stderr)
TWO_SIDED = ("*CONTACT_ERODING_NODES_TO_SURFACE\n$#    ssid      msid     sstyp     mstyp\n"
             "         2         1         3         3\n\n\n         0         1         0\n")
d = write(os.path.join(WORK, "eroding_nodes"), "model.k", fast.replace(CONTACT, TWO_SIDED))
t = write(os.path.join(WORK, "eroding_nodes"), "model.yaml",
          fast_twin.replace("  - {type: self, elements: all}", "  - {type: self, elements: [part_2, part_1]}"))
twin_pair("*CONTACT_ERODING_NODES_TO_SURFACE: the block's nodes against the failing plate", d, t)
# its slave side a node set (SSTYP 4): the block's outer nodes alone against the plate's faces
# (one-way), as the twin's self-contact with `nodes`
BLOCK_SET = "*SET_NODE_LIST\n         2\n" + "".join(
    "%10d" % n + ("\n" if i % 8 == 7 else "")
    for i, n in enumerate([n for n in range(201, 228) if n != 214] + list(range(301, 308)))) + "\n"
NODE_SET_SIDE = TWO_SIDED.replace("         2         1         3         3",
                                  "         2         1         4         3")
d = write(os.path.join(WORK, "eroding_node_set"), "model.k",
          fast.replace(CONTACT, NODE_SET_SIDE).replace("*END", BLOCK_SET + "*END"))
t = write(os.path.join(WORK, "eroding_node_set"), "model.yaml",
          fast_twin.replace("  - {type: self, elements: all}",
                            "  - {type: self, elements: part_1, nodes: block_nodes}"))
one_way = twin_pair("*CONTACT_ERODING_NODES_TO_SURFACE of a node set: the block's nodes against the plate", d, t)
check("a node set against the plate's faces (one-way) is not the two-way contact of both parts",
      one_way is not None and perforated is not None and one_way != perforated)
refused("an eroding contact without its fourth card", deck.replace(CONTACT, ERODING[:ERODING.index("$#    isym")]),
        "model.k:", "*CONTACT_ERODING_SINGLE_SURFACE", "ISYM, EROSOP, IADJ")
refused("EROSOP 2", deck.replace(CONTACT, ERODING.replace("         0         1         0\n",
                                                           "         0         2         0\n")),
        "model.k:", "*CONTACT_ERODING_SINGLE_SURFACE", "EROSOP must be 0 or 1")


PLATE = "*PART\nplate\n         1         1         1\n"
assert PLATE in deck
refused("inertia of a deformable part",
        deck.replace(PLATE, INERTIA.replace("block\n         2         2         2",
                                            "plate\n         1         1         1")),
        "model.k:", "*PART_INERTIA", "rigid parts (*MAT_RIGID) only")
refused("local axes", deck.replace(PART, INERTIA.replace("1.2         0", "1.2         1")),
        "model.k:", "*PART_INERTIA", "IRCS 1")
refused("a node as the centre", deck.replace(PART, INERTIA.replace("0         0\n$#     ixx",
                                                                   "0       205\n$#     ixx")),
        "model.k:", "*PART_INERTIA", "NODEID")
refused("no mass", deck.replace(PART, INERTIA.replace("       1.2", "       0.0")),
        "model.k:", "*PART_INERTIA", "TM")
sys.exit(finish())

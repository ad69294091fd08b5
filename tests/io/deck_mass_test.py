#!/usr/bin/env python3
"""Point masses of decks (model-format.md `masses`): plate_drop.k with *ELEMENT_MASS (nodes 41
and 42 of 0.5 kg each, node 43 of 0.25 kg with a PID, noted) and *ELEMENT_MASS_NODE_SET (2 kg
shared by nodes 1-4) against its YAML twin with the same `masses`: the same history.csv bytes,
and `check` counts 3.25 kg more than the plate's 0.157 kg. Refusals, exit 2 with one sentence
naming the card: a part's mass by a curve (LCID), *ELEMENT_MASS_MATRIX, a mass that is not > 0,
a node the deck does not define. MAREA and *ELEMENT_MASS_PART (ADDMASS, FINMASS) against the
twin's `area_mass` and masses spread on elements. A mass on a node of no shell, hung by a nodal rigid body, is a particle of its own.

usage: deck_mass_test.py FPMSHELL WORKDIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_variant  # noqa: E402
from deck_variant import fpmshell, read, twin_pair  # noqa: E402

WORK, DROP, deck, twin, write = deck_variant.start(sys.argv, "plate_drop")
AT = "*INITIAL_VELOCITY_GENERATION"
assert AT in deck and "\nsets:\n" in twin and "\ninitial_conditions:" in twin


def mass_card(eid, node, mass, pid=None):
    return "%8d%8d%16.4f%s\n" % (eid, node, mass, "" if pid is None else "%8d" % pid)


MASSES = ("*ELEMENT_MASS\n$#   eid     nid            mass     pid\n" +
          mass_card(900001, 41, 0.5) + mass_card(900002, 42, 0.5) + mass_card(900003, 43, 0.25, 1) +
          "*SET_NODE_LIST\n        77\n         1         2         3         4\n"
          "*ELEMENT_MASS_NODE_SET\n" + mass_card(900004, 77, 2.0))
folder = os.path.join(WORK, "masses")
d = write(folder, "model.k", deck.replace(AT, MASSES + AT, 1))
t = write(folder, "model.yaml", twin.replace(
    "\nsets:\n", "\nsets:\n  weights: {node_ids: [41, 42]}\n  weight: {node_ids: [43]}\n"
                 "  corners: {node_ids: [1, 2, 3, 4]}\n").replace(
    "\ninitial_conditions:", "\nmasses:\n  - {nodes: weights, mass: 0.5}\n  - {nodes: weight, mass: "
                             "0.25}\n  - {nodes: corners, total: 2}\n\ninitial_conditions:"))
twin_pair("point masses", d, t)
c = fpmshell("check", d)
check("point masses: check counts them in the total and notes the PID",
      c.returncode == 0 and "total mass 3.407" in c.stdout and
      "point masses 3.25 on 7 particles" in c.stdout and "PID: the mass joins its node" in c.stdout,
      c.stdout + c.stderr)
plain = fpmshell("check", os.path.join(DROP, "plate_drop.k"))
check("point masses: the plate alone weighs 0.157 kg", "total mass 0.157" in plain.stdout,
      plain.stdout)

for name, cards, words in (
        ("a part's mass by a curve", "*ELEMENT_MASS_PART\n       1            10.0"
                                     "             0.0               7\n",
         ("*ELEMENT_MASS_PART", "LCID")),
        ("a matrix of masses", "*ELEMENT_MASS_MATRIX\n       1       1\n",
         ("*ELEMENT_MASS_MATRIX", "this form of it is not supported")),
        ("a mass not > 0", "*ELEMENT_MASS\n" + mass_card(900001, 41, 0.0), ("MASS must be > 0",)),
        ("a mass on an undefined node", "*ELEMENT_MASS\n" + mass_card(900001, 90001, 1.0),
         ("*ELEMENT_MASS", "node 90001"))):
    path = write(os.path.join(WORK, name.replace(" ", "_").replace("'", "")), "model.k",
                 deck.replace(AT, cards + AT, 1))
    r = fpmshell("check", path)
    errors = [line for line in r.stderr.splitlines() if line.startswith("error:")]
    check(f"{name}: exit 2 with one sentence naming the card", r.returncode == 2 and
          len(errors) == 1 and "model.k:" in errors[0] and all(w in errors[0] for w in words),
          r.stderr)

# Non-structural mass: MAREA of 5 kg/m^2 on the section (the plate of 0.1 m x 0.1 m: 0.05 kg)
# and *ELEMENT_MASS_PART spreading 0.3 kg more over part 1 by area, against the twin's
# `area_mass` and `masses: - {elements: part_1, total: 0.3}`; then FINMASS 1.0 (the part's mass
# once added, MAREA's included), the twin's `final: 1`.
SECTION_T = "$#      t1        t2        t3        t4      nloc\n    &thick    &thick    &thick    &thick"
assert SECTION_T in deck
nsm_deck = deck.replace(SECTION_T, SECTION_T + "       0.0       5.0", 1)
for name, card, entry, total in (
        ("area and part masses", "%8d%16.4f%16.4f\n" % (1, 0.3, 0.0), "total: 0.3", "0.507"),
        ("a part's final mass", "%8d%16.4f%16.4f\n" % (1, 0.0, 1.0), "final: 1", "1\n")):
    folder = os.path.join(WORK, name.replace(" ", "_").replace("'", ""))
    d = write(folder, "model.k", nsm_deck.replace(AT, "*ELEMENT_MASS_PART\n" + card + AT, 1))
    t = write(folder, "model.yaml", twin.replace(
        "thickness: 0.002,", "thickness: 0.002, area_mass: 5,").replace(
        "\ninitial_conditions:", "\nmasses:\n  - {elements: part_1, %s}\n\ninitial_conditions:"
        % entry))
    assert "area_mass: 5" in read(t)
    twin_pair(name, d, t)
    c = fpmshell("check", d)
    check(f"{name}: check counts the plate's 0.157 kg and the masses ({total.strip()} kg in all)",
          c.returncode == 0 and "total mass %s" % total in c.stdout, c.stdout + c.stderr)

# A mass of 1.5 kg on a node of no shell above the plate's centre, joined to three plate nodes by
# *CONSTRAINED_NODAL_RIGID_BODY (an engine's mass hung on a structure): the node is a particle of
# its own, the body's motion carries it, and the run closes its energy balance. A model whose
# mesh file keeps such a node but gives it no mass is refused naming `mesh`.
HUNG = ("*NODE\n   90001            0.05            0.05            0.08\n*ELEMENT_MASS\n" +
        mass_card(900010, 90001, 1.5) + "*SET_NODE_LIST\n        78\n     90001        40        41"
        "        42\n*CONSTRAINED_NODAL_RIGID_BODY\n       500         0        78\n")
d = write(os.path.join(WORK, "hung_mass"), "model.k", deck.replace(AT, HUNG + AT, 1))
c = fpmshell("check", d)
check("a hung mass: its node is a particle (82) and its mass counts (0.157 + 1.5 kg)",
      c.returncode == 0 and "particles  82" in c.stdout and "total mass 1.657" in c.stdout and
      "nodal rigid bodies: 1 (4 particles)" in c.stdout, c.stdout + c.stderr)
r = fpmshell("run", d, "-o", os.path.join(WORK, "hung_mass", "out"), "--quiet", "--overwrite")
summary = read(os.path.join(WORK, "hung_mass", "out", "summary.json")) if r.returncode == 0 else ""
error = float(summary.split('"energy_error":')[1].split(",")[0]) if summary else 1.0
check("a hung mass: the run closes its energy balance (|error| < 1e-4)", abs(error) < 1e-4,
      r.stderr[-400:] + summary[:300])
mesh_with_mass = read(os.path.join(DROP, "plate_drop_mesh.k")).replace(
    "*END", "*NODE\n   90001            0.05            0.05            0.08\n*ELEMENT_MASS\n" +
    mass_card(900010, 90001, 1.5) + "*END")
folder = deck_variant.write_files(os.path.join(WORK, "massless"),
                                  {"plate_drop_mesh.k": mesh_with_mass, "model.yaml": twin})
r = fpmshell("check", os.path.join(folder, "model.yaml"))
check("a mesh file's mass node without `masses`: exit 2 naming mesh and the particle",
      r.returncode == 2 and "key 'mesh'" in r.stderr and "no entry of `masses`" in r.stderr,
      r.stderr)

# A mass on the rigid block of block_drop.k (2 x 2 x 2 hexahedra): on a node of its surface it
# joins the body (check counts it); on its centre node, inside (on none of the outer faces that
# carry the body), it is refused naming the card.
BLOCK_DIR = os.path.join(os.path.dirname(DROP), "block_drop")
block = read(os.path.join(BLOCK_DIR, "block_drop.k"))
BLOCK_AT = "*INITIAL_VELOCITY_NODE"
assert BLOCK_AT in block
plain_block = fpmshell("check", os.path.join(BLOCK_DIR, "block_drop.k"))
plain_total = [ln for ln in plain_block.stdout.splitlines() if ln.startswith("total mass")]
for name, node, ok in (("a mass on the block's surface", 201, True),
                       ("a mass inside the block", 214, False)):
    path = write(os.path.join(WORK, name.replace(" ", "_").replace("'", "")), "model.k",
                 block.replace(BLOCK_AT, "*ELEMENT_MASS\n" + mass_card(900001, node, 0.5) +
                               BLOCK_AT, 1), mesh=os.path.join(BLOCK_DIR, "block_drop_mesh.k"))
    r = fpmshell("check", path)
    if ok:
        check(f"{name}: the body gains it (check: 0.5 more in all)",
              r.returncode == 0 and plain_total and "point masses 0.5 on 1 particles" in r.stdout,
              r.stdout + r.stderr)
    else:
        check(f"{name}: exit 2 with one sentence naming the card's line", r.returncode == 2 and
              r.stderr.count("error:") == 1 and "node 214 carries a point mass inside a rigid "
              "part of solids" in r.stderr and "model.k:" in r.stderr, r.stderr)

sys.exit(finish())

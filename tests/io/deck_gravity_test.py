#!/usr/bin/env python3
"""Gravity in decks (theory.md eq. 6.7-4; docs/decks.md *LOAD_BODY): plate_drop.k with
*LOAD_BODY_Z of a curve at 9.81 against its YAML twin with `{type: gravity, value: [0, 0, -1]}`
on the same curve: the same history.csv bytes, and the plate falls faster than without, its
corner's velocity -5 - 9.81 t before it meets the floor. *LOAD_BODY_PARTS naming the plate's part
changes no byte (every element is of that part); *LOAD_BODY_X and _Y pull along -x and -y.
Refusals, exit 2 with one sentence naming the card: a rotation (*LOAD_BODY_RZ), a local system
(CID), no curve (LCID 0).

usage: deck_gravity_test.py FPMSHELL WORKDIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_variant  # noqa: E402
from deck_variant import fpmshell, read, run, twin_pair  # noqa: E402

WORK, DROP, deck, twin, write = deck_variant.start(sys.argv, "plate_drop")
AT = "*INITIAL_VELOCITY_GENERATION"
assert AT in deck and "\ninitial_conditions:" in twin
G_CURVE = "*DEFINE_CURVE\n       901\n                 0.0                9.81\n" \
          "                 1.0                9.81\n"


def body(keyword, card="       901"):
    return "%s\n%s\n%s" % (keyword, card, G_CURVE)


def columns(history):
    lines = history.strip().splitlines()
    names = lines[0].split(",")
    return {n: [float(r.split(",")[k]) for r in lines[1:]] for k, n in enumerate(names)}


folder = os.path.join(WORK, "gravity")
d = write(folder, "model.k", deck.replace(AT, body("*LOAD_BODY_Z") + AT, 1))
t = write(folder, "model.yaml", twin.replace(
    "\ninitial_conditions:", "\ncurves:\n  g: [[0, 9.81], [1, 9.81]]\n\nloads:\n"
                             "  - {type: gravity, value: [0, 0, -1], curve: g}\n\ninitial_conditions:"))
history = twin_pair("*LOAD_BODY_Z", d, t)
r_plain, h_plain = run(write(os.path.join(WORK, "plain"), "model.k", deck))
if history and r_plain.returncode == 0:
    fall, free = columns(history), columns(read(h_plain))
    # the first rows, before the plate meets the floor (it starts 5 m/s above it ... the
    # plain run's corner still moves at -5 m/s there)
    rows = [k for k in range(1, len(free["time"])) if abs(free["node1_vz"][k] + 5) < 1e-9]
    check("*LOAD_BODY_Z: rows before the plate meets the floor", len(rows) >= 3, rows)
    worst = max((abs(fall["node1_vz"][k] - (-5 - 9.81 * fall["time"][k])) for k in rows), default=1)
    # the velocity of a row is v^{n+1/2}, half a step (about 1 us) after the row's time
    check("*LOAD_BODY_Z: the corner falls at -5 - 9.81 t before it meets the floor", worst < 1e-4,
          worst)
for name, cards, expect in (("*LOAD_BODY_PARTS", body("*LOAD_BODY_Z") +
                             "*SET_PART_LIST\n        70\n         1\n*LOAD_BODY_PARTS\n        70\n",
                             history),):
    path = write(os.path.join(WORK, "parts"), "model.k", deck.replace(AT, cards + AT, 1))
    r, h = run(path)
    check(f"{name}: the history of the plain body load (every element is of the part)",
          r.returncode == 0 and expect is not None and read(h) == expect, r.stderr)
    converted = fpmshell("convert", path, "-o", os.path.join(WORK, "parts", "converted.yaml"))
    check(f"{name}: the converted model loads the part set's elements",
          converted.returncode == 0 and "type: gravity" in read(os.path.join(WORK, "parts", "converted.yaml"))
          and ", elements: " in read(os.path.join(WORK, "parts", "converted.yaml")), converted.stderr)
for keyword, value in (("*LOAD_BODY_X", "[-1, 0, 0]"), ("*LOAD_BODY_Y", "[0, -1, 0]")):
    path = write(os.path.join(WORK, keyword[1:]), "model.k", deck.replace(AT, body(keyword) + AT, 1))
    converted = fpmshell("convert", path, "-o", os.path.join(WORK, keyword[1:], "converted.yaml"))
    check(f"{keyword}: gravity along the axis's negative direction",
          converted.returncode == 0 and "type: gravity, value: %s" % value in
          read(os.path.join(WORK, keyword[1:], "converted.yaml")), converted.stderr)
for name, cards, words in (
        ("a rotation", body("*LOAD_BODY_RZ"), ("*LOAD_BODY_RZ", "*LOAD_BODY_X, _Y, _Z")),
        ("a local system", body("*LOAD_BODY_Z", "       901       1.0         0       0.0       0.0"
                                                "       0.0         5"), ("*LOAD_BODY_Z", "CID")),
        ("no curve", body("*LOAD_BODY_Z", "         0"), ("*LOAD_BODY_Z", "LCID"))):
    path = write(os.path.join(WORK, name.replace(" ", "_")), "model.k", deck.replace(AT, cards + AT, 1))
    r = fpmshell("check", path)
    check(f"{name}: exit 2 with one sentence naming the card",
          r.returncode == 2 and all(w in r.stderr for w in words) and "model.k:" in r.stderr and
          len(r.stderr.strip().splitlines()) == 1, r.stderr)

sys.exit(finish())

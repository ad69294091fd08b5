"""The air blast of decks (docs/decks.md; theory.md §6.13), each a variant of
examples/decks/blast_panel (10 g of TNT over a clamped panel, *LOAD_BLAST_ENHANCED on a
*SET_SEGMENT) against the panel as it is or against a YAML twin, the same history.csv bytes:

- the faces as single *LOAD_BLAST_SEGMENT cards: the segment set's history;
- the segments listed the other way round (-> `reversed: true`) with the charge below the panel:
  its twin, and the mirror image of the panel's motion;
- the panel stays still until the shock arrives, then moves away from the charge; `check` prints
  the charge;
- NEGPHS 0 (also blank, and without card 2) and 10: the negative phase, as its twin with
  `negative_phase: true`, and a history other than NEGPHS 1's; NEGPHS 11: NEGPHS 1's history;
- refusals with exit 2 and one sentence naming the place: BLAST 3, UNIT 1, a BID no
  *LOAD_BLAST_ENHANCED defines, ALEPID (ALE coupling).

usage: deck_blast_test.py FPMSHELL WORKDIR
"""
import os
import shutil
import sys

FPM, WORK = sys.argv[1], sys.argv[2]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECKS = os.path.join(ROOT, "examples", "decks")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_variant  # noqa: E402
from deck_variant import fpmshell, read, run, twin_pair  # noqa: E402
from deck_variant import write as write_beside  # noqa: E402

deck_variant.FPM = FPM
MESH = os.path.join(DECKS, "pressure_panel", "pressure_panel_mesh.k")
shutil.rmtree(WORK, ignore_errors=True)

# the panel's deck and twin, their mesh beside them in each variant's folder
INCLUDED = "../pressure_panel/pressure_panel_mesh.k"
deck = read(os.path.join(DECKS, "blast_panel", "blast_panel.k")).replace(INCLUDED, "pressure_panel_mesh.k")
twin = read(os.path.join(DECKS, "blast_panel", "blast_panel.yaml")).replace(INCLUDED, "pressure_panel_mesh.k")
SOURCE_CARD = "         1      0.01      0.15      0.15       0.3    0.0002         2         2\n"
SET_LOAD = "*LOAD_BLAST_SEGMENT_SET\n         1         3\n"
assert SOURCE_CARD in deck and SET_LOAD in deck
segments = deck[deck.index("*SET_SEGMENT\n"):deck.index("*LOAD_BLAST_SEGMENT_SET")]
BLAST_LINE = "  - {type: blast, elements: shell_set_7, charge_mass: 0.01, centre: [0.15, 0.15, 0.3],"
assert BLAST_LINE in twin


def write(folder, name, text):
    return write_beside(os.path.join(WORK, folder), name, text, MESH)


def uz(history_text):
    rows = [line.split(",") for line in history_text.splitlines()]
    k = rows[0].index("node61_uz")
    return [float(r[k]) for r in rows[1:]]


# the panel as it is
h_set = twin_pair("blast on a segment set", write("set", "model.k", deck),
                  write("set", "model.yaml", twin))
if h_set:
    w = uz(h_set)
    check("blast on a segment set: still before the shock, then pushed away from the charge (-z)",
          min(w) < -1e-3 and abs(w[25]) < 1e-20, "uz %g ... %g" % (w[25], min(w)))
r = fpmshell("check", os.path.join(WORK, "set", "model.k"))
check("blast: check prints the charge",
      r.returncode == 0 and "blast of 0.01 TNT (free air)" in r.stdout, r.stdout + r.stderr)

# the same faces as single segment cards (BID N1 N2 N3 N4)
cards = [line for line in segments.splitlines()[2:] if line.strip()]
single = deck.replace(segments + SET_LOAD,
                      "*LOAD_BLAST_SEGMENT\n" + "".join(f"{1:10d}" + c[:40] + "\n" for c in cards))
r_single, h_single = run(write("single", "model.k", single))
check("blast on single segments: runs", r_single.returncode == 0, r_single.stderr)
check("blast on single segments: the segment set's history",
      h_set is not None and r_single.returncode == 0 and read(h_single) == h_set)


# the segments listed the other way round, the charge below: the mirror image
def reverse(card):
    nodes = [card[10 * k:10 * k + 10] for k in range(4)]
    return "".join(reversed(nodes))


mirrored = deck.replace(SOURCE_CARD, SOURCE_CARD.replace("       0.3    0.0002", "      -0.3    0.0002"))
mirrored = mirrored.replace(segments, "*SET_SEGMENT\n         3\n" + "".join(reverse(c) + "\n" for c in cards))
mirrored_twin = twin.replace(BLAST_LINE, BLAST_LINE.replace("0.15, 0.3]", "0.15, -0.3], reversed: true"))
h_mirror = twin_pair("blast on reversed segments, the charge below",
                     write("mirror", "model.k", mirrored), write("mirror", "model.yaml", mirrored_twin))
if h_set and h_mirror:
    a, b = uz(h_set), uz(h_mirror)
    worst = max(abs(x + y) for x, y in zip(a, b)) / max(abs(x) for x in a)
    check("blast on reversed segments, the charge below: the mirror image of the panel's motion",
          worst < 1e-9, f"largest difference {worst:.3g}")

# NEGPHS: 0 (written, blank, or card 2 left out) and 10 continue the pulses past their positive
# phase (theory.md eq. 6.13-5) as the twin with negative_phase: true; 11 is 1 (the panel's)
NEGPHS_CARD = "                                                       0.004         1\n"
assert NEGPHS_CARD in deck
negative_twin = twin.replace("death_time: 0.004}", "death_time: 0.004, negative_phase: true}")
assert negative_twin != twin
h_negative = twin_pair("blast NEGPHS 0", write("negphs0", "model.k", deck.replace(NEGPHS_CARD, NEGPHS_CARD[:-11] + "         0\n")),
                       write("negphs0", "model.yaml", negative_twin))
check("blast NEGPHS 0: the negative phase changes the panel's motion",
      h_set is not None and h_negative is not None and h_negative != h_set)
for name, card in (("blank", NEGPHS_CARD[:-11] + "\n"), ("10", NEGPHS_CARD[:-11] + "        10\n")):
    r_n, h_n = run(write("negphs_" + name, "model.k", deck.replace(NEGPHS_CARD, card)))
    check(f"blast NEGPHS {name}: NEGPHS 0's history",
          r_n.returncode == 0 and h_negative is not None and read(h_n) == h_negative, r_n.stderr)
without_card_2 = deck.replace("$#     cfm       cfl       cft       cfp     nidbo     death    negphs\n" + NEGPHS_CARD, "")
assert without_card_2 != deck
r_n, h_n = run(write("negphs_no_card", "model.k", without_card_2))
# without card 2 there is no DEATH either: the same as NEGPHS 0 up to 4 ms, then still loaded
check("blast without card 2: NEGPHS 0's history up to DEATH",
      r_n.returncode == 0 and h_negative is not None
      and read(h_n).splitlines()[:400] == h_negative.splitlines()[:400], r_n.stderr)
r_n, h_n = run(write("negphs_11", "model.k", deck.replace(NEGPHS_CARD, NEGPHS_CARD[:-11] + "        11\n")))
check("blast NEGPHS 11: NEGPHS 1's history", r_n.returncode == 0 and h_set is not None and read(h_n) == h_set,
      r_n.stderr)

# refusals: exit 2, one sentence naming the deck's file and line
for name, text, message in (
        ("BLAST 3", deck.replace(SOURCE_CARD, SOURCE_CARD[:-11] + "         3\n"), "BLAST 3"),
        ("UNIT 1", deck.replace(SOURCE_CARD, SOURCE_CARD[:-21] + "         1         2\n"), "UNIT 1"),
        ("no charge", deck.replace(SET_LOAD, "*LOAD_BLAST_SEGMENT_SET\n         2         3\n"),
         "no *LOAD_BLAST_ENHANCED defines it"),
        ("ALE coupling", deck.replace(SET_LOAD, "*LOAD_BLAST_SEGMENT_SET\n         1         3         5\n"),
         "ALEPID")):
    path = write("refused_" + name.replace(" ", "_"), "model.k", text)
    r = fpmshell("check", path)
    errors = [line for line in r.stderr.splitlines() if line.startswith("error:")]
    check(f"blast refused: {name}", r.returncode == 2 and len(errors) == 1 and message in errors[0]
          and "model.k:" in errors[0], r.stderr)

finish()

"""The rules through the thickness of decks (docs/decks.md; theory.md §4.5):

- *SECTION_SHELL NIP 1-10 is read as LS-DYNA's Gauss rule, *CONTROL_SHELL INTGRD 1 as Lobatto
  (3-10 points), QR < 0 as the *INTEGRATION_SHELL rule |QR| (points given, or ESOP 1: equal
  layers): each variant of plate_drop.k gives the same history.csv bytes as its YAML twin with
  `thickness_points` / `thickness_rule`, and the rules give different histories (the key reaches
  the solver);
- NIP 1 is a membrane (noted), weights that sum to 1 within 1e-3 are scaled (noted), and NIP 11,
  QR 1, a missing rule, a YAML Lobatto rule of 2 points and YAML weights that do not sum to 1 are
  refused with exit 2 and one sentence naming the place.

usage: deck_rules_test.py FPMSHELL WORKDIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_variant  # noqa: E402
from deck_variant import fpmshell, read, run, twin_pair  # noqa: E402

WORK, DROP, deck, twin, write = deck_variant.start(sys.argv, "plate_drop")
SECTION = "         1         2    0.8333         5         1\n"
TWIN_SECTION = "thickness: 0.002, thickness_points: 5, thickness_rule: gauss}"
assert SECTION in deck and TWIN_SECTION in twin
END = "*END\n"
assert deck.endswith(END)

VARIANTS = {  # name: (section card, cards added to the deck, the twin's section keys)
    "NIP 5 (Gauss, as LS-DYNA)": (SECTION, "", TWIN_SECTION),
    "NIP 7": ("         1         2    0.8333         7\n", "",
              "thickness: 0.002, thickness_points: 7, thickness_rule: gauss}"),
    "INTGRD 1, NIP 4 (Lobatto)": (
        "         1         2    0.8333         4\n",
        "*CONTROL_SHELL\n$#  wrpang     esort     irnxx    istupd    theory       bwc     miter      proj\n"
        "\n$# rotascl    intgrd\n       1.0         1\n",
        "thickness: 0.002, thickness_points: 4, thickness_rule: lobatto}"),
    "INTGRD 1, NIP 2 (Gauss: LS-DYNA's Lobatto has 3 points at least)": (
        "         1         2    0.8333         2\n",
        "*CONTROL_SHELL\n\n                   1\n",
        "thickness: 0.002, thickness_points: 2}"),
    "QR -3, *INTEGRATION_SHELL of three points": (
        "         1         2    0.8333         3         1        -3\n",
        "*INTEGRATION_SHELL\n         3         3\n      -0.8      0.25\n       0.0       0.5\n"
        "       0.8      0.25\n",
        "thickness: 0.002, thickness_rule: [[-0.8, 0.25], [0, 0.5], [0.8, 0.25]]}"),
    "QR -4, *INTEGRATION_SHELL ESOP 1 (four equal layers)": (
        "         1         2    0.8333         4         1        -4\n",
        "*INTEGRATION_SHELL\n         4         4         1\n",
        "thickness: 0.002, thickness_points: 4,\n"
        "     thickness_rule: [[-0.75, 0.25], [-0.25, 0.25], [0.25, 0.25], [0.75, 0.25]]}"),
}
histories = {}
for k, (name, (section, cards, keys)) in enumerate(VARIANTS.items()):
    folder = os.path.join(WORK, f"rule{k}")
    d = write(folder, "model.k", deck.replace(SECTION, section)[:-len(END)] + cards + END)
    t = write(folder, "model.yaml", twin.replace(TWIN_SECTION, keys))
    history = twin_pair(name, d, t)
    if history is not None:
        histories[name] = history
# card order is free for these cards too: *CONTROL_SHELL and *INTEGRATION_SHELL before the
# sections that use them (after *KEYWORD) give the same bytes
for k, name in ((2, "INTGRD 1, NIP 4 (Lobatto)"), (4, "QR -3, *INTEGRATION_SHELL of three points")):
    section, cards, keys = VARIANTS[name]
    early = deck.replace(SECTION, section).replace("*KEYWORD\n", "*KEYWORD\n" + cards, 1)
    assert early != deck.replace(SECTION, section)
    d = write(os.path.join(WORK, f"early{k}"), "model.k", early)
    r_early, h_early = run(d)
    check(f"{name}: the card first in the deck, the same history.csv",
          r_early.returncode == 0 and name in histories and read(h_early) == histories[name],
          r_early.stderr)

check("the rules give different histories (the rule reaches the solver)",
      len(set(histories.values())) == len(histories), f"{len(set(histories.values()))} distinct")

# what `check` says of each
c = fpmshell("check", os.path.join(WORK, "rule2", "model.k"))
check("check: a Lobatto section of 4 points", c.returncode == 0 and "4 Lobatto x 3 points" in c.stdout,
      c.stdout + c.stderr)
c = fpmshell("check", os.path.join(WORK, "rule0", "model.k"))
check("check: NIP 5 is 5 Gauss points", c.returncode == 0 and "5 Gauss x 3 points" in c.stdout,
      c.stdout + c.stderr)


def deck_case(name, section, cards=""):
    path = write(os.path.join(WORK, name), "model.k",
                 deck.replace(SECTION, section)[:-len(END)] + cards + END)
    return path, fpmshell("check", path)


path, r = deck_case("membrane", "         1         2    0.8333         1\n")
check("NIP 1: one point, noted as a membrane", r.returncode == 0 and "1 Gauss x 3 points" in r.stdout
      and "carries no bending moment" in r.stdout, r.stdout + r.stderr)
path, r = deck_case("thirds", "         1         2    0.8333         3         1        -5\n",
                    "*INTEGRATION_SHELL\n         5         3\n   -0.6667    0.3333\n"
                    "       0.0    0.3333\n    0.6667    0.3333\n")
check("weights of 0.3333 are scaled to sum to 1, noted",
      r.returncode == 0 and "WF sum to 0.9999: scaled to sum to 1" in r.stdout and
      "3 user x 3 points" in r.stdout, r.stdout + r.stderr)


def refused(name, r, *words):
    check(f"{name}: exit 2, one sentence naming the place",
          r.returncode == 2 and all(w in r.stderr for w in words) and
          len(r.stderr.strip().splitlines()) == 1, r.stderr)


path, r = deck_case("nip11", "         1         2    0.8333        11\n")
refused("NIP 11", r, "model.k:", "*SECTION_SHELL", "NIP 11", "1 to 10")
path, r = deck_case("trapezoid", "         1         2    0.8333         5         1         1\n")
refused("QR 1 (trapezoidal)", r, "model.k:", "*SECTION_SHELL", "trapezoidal")
path, r = deck_case("no rule", "         1         2    0.8333         3         1        -9\n")
refused("QR -9 without its *INTEGRATION_SHELL", r, "model.k:", "QR/IRID -9",
        "no *INTEGRATION_SHELL 9")
path, r = deck_case("weights", "         1         2    0.8333         3         1        -6\n",
                    "*INTEGRATION_SHELL\n         6         2\n      -0.5       0.3\n       0.5       0.3\n")
refused("weights that sum to 0.6", r, "model.k:", "*INTEGRATION_SHELL", "sum to 0.6")

for name, keys, words in (
        ("yaml lobatto 2", "thickness: 0.002, thickness_points: 2, thickness_rule: lobatto}",
         ("model.yaml:", "thickness_points", "Lobatto rule has 3 to 10 points")),
        ("yaml weights", "thickness: 0.002, thickness_rule: [[-0.5, 0.5], [0.5, 0.4]]}",
         ("model.yaml:", "thickness_rule", "sum to 1")),
        ("yaml zeta", "thickness: 0.002, thickness_rule: [[-1.5, 0.5], [0.5, 0.5]]}",
         ("model.yaml:", "thickness_rule", "zeta must lie in [-1, 1]")),
        ("yaml 11 points", "thickness: 0.002, thickness_points: 11}",
         ("model.yaml:", "thickness_points")),
        ("yaml family", "thickness: 0.002, thickness_rule: newton}",
         ("model.yaml:", "thickness_rule", "gauss"))):
    path = write(os.path.join(WORK, name.replace(" ", "_")), "model.yaml",
                 twin.replace(TWIN_SECTION, keys))
    refused(name, fpmshell("check", path), *words)

sys.exit(finish())

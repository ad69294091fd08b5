"""Material cards of LS-DYNA decks against their YAML twins (docs/decks.md), the same history.csv
bytes through both readers:

- *MAT_SIMPLIFIED_JOHNSON_COOK (098) on tube_crush.k: the *MAT_JOHNSON_COOK deck's bytes, PSFAIL,
  its default written out, the caps refused;
- *MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY (123) on strip_pull.k: *MAT_024's bytes, EPSMAJ,
  EPSTHIN, refusals;
- LCSR of *MAT_024 and *MAT_081 (theory.md eq. 7.4-3) on strip_pull.k: the twin's rate_scaling,
  the pull it changes, beside a table (noted) and beside C, P (refused).

usage: deck_material_test.py FPMSHELL WORKDIR
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_twins  # noqa: E402
from deck_twins import check_erodes, deck_against_twin, read, write_case  # noqa: E402

FPM, WORK = deck_twins.start(sys.argv)
DECKS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                     "examples", "decks")
TUBE = os.path.join(DECKS, "tube_crush")
tube_deck, tube_twin = read(os.path.join(TUBE, "tube_crush.k")), read(os.path.join(TUBE, "tube_crush.yaml"))
STRIP = os.path.join(DECKS, "strip_pull")
strip_deck, strip_twin = read(os.path.join(STRIP, "strip_pull.k")), read(os.path.join(STRIP, "strip_pull.yaml"))
JC_TWIN = "    reference_strain_rate: 1.0\n"
STRIP_MAT = "$#     mid        ro         e        pr      sigy\n         1    7850.0   2.1e+11       0.3   3.0e+08\n"
assert JC_TWIN in tube_twin and STRIP_MAT in strip_deck
# the *MAT_JOHNSON_COOK deck as it is (isothermal: its CP is 0), the bytes the simplified card gives
h_cold = deck_against_twin("*MAT_JOHNSON_COOK", os.path.join(WORK, "johnson_cook"),
                           os.path.join(TUBE, "tube_crush_mesh.k"), tube_deck, tube_twin)

# ---- *MAT_SIMPLIFIED_JOHNSON_COOK (098): tube_crush.k's steel written as the simplified card
# (EPSO blank: 1, its default), the same history.csv bytes as the *MAT_JOHNSON_COOK deck
# (isothermal: its CP is 0); with PSFAIL against the twin with failure: {plastic_strain}, the
# folds erode; caps on the flow stress (SIGMAX, SIGSAT) and PSFAIL < 0 refused.
JC_CARDS = tube_deck[tube_deck.index("*MAT_JOHNSON_COOK"):tube_deck.index("*EOS_LINEAR_POLYNOMIAL")]
SIMPLIFIED = ("*MAT_SIMPLIFIED_JOHNSON_COOK\n$#     mid        ro         e        pr        vp\n"
              "         1    7850.0   2.1e+11       0.3\n"
              "$#       a         b         n         c    psfail    sigmax    sigsat      epso\n"
              "   2.5e+08   4.0e+08      0.45     0.015%s\n")
h_simple = deck_against_twin(
    "simplified Johnson-Cook", os.path.join(WORK, "simplified_jc"), os.path.join(TUBE, "tube_crush_mesh.k"),
    tube_deck.replace(JC_CARDS, SIMPLIFIED % ""), tube_twin)
check("simplified Johnson-Cook: the history of the *MAT_JOHNSON_COOK deck, byte for byte",
      h_simple is not None and h_cold is not None and read(h_simple) == read(h_cold), "the files differ")
h_psfail = deck_against_twin(
    "simplified Johnson-Cook PSFAIL", os.path.join(WORK, "simplified_jc_fail"),
    os.path.join(TUBE, "tube_crush_mesh.k"), tube_deck.replace(JC_CARDS, SIMPLIFIED % "      0.15"),
    tube_twin.replace(JC_TWIN, JC_TWIN + "    failure: {plastic_strain: 0.15}\n"))
check_erodes("simplified Johnson-Cook PSFAIL: the tube's folds erode", h_psfail)
h_default = deck_against_twin(
    "simplified Johnson-Cook PSFAIL at its default", os.path.join(WORK, "simplified_jc_default"),
    os.path.join(TUBE, "tube_crush_mesh.k"), tube_deck.replace(JC_CARDS, SIMPLIFIED % "     1e+17"),
    tube_twin)
check("simplified Johnson-Cook: PSFAIL 1e17 written out (LS-DYNA's default) is no criterion",
      h_default is not None and h_simple is not None and read(h_default) == read(h_simple),
      "the files differ")
for name, fields, message in (("SIGMAX", "       0.0     5e+08", "SIGMAX (a cap on the flow stress)"),
                              ("SIGSAT", "       0.0      1e28     6e+08", "SIGSAT (a cap on the flow stress)"),
                              ("PSFAIL < 0", "      -1.0", "PSFAIL < 0")):
    folder = write_case("simplified_jc_bad", tube_deck.replace(JC_CARDS, SIMPLIFIED % fields),
                        os.path.join(TUBE, "tube_crush_mesh.k"))
    r = subprocess.run([FPM, "check", os.path.join(folder, "model.k")], capture_output=True, text=True)
    check(f"simplified Johnson-Cook: {name} refused with exit 2 and one sentence naming the card",
          r.returncode == 2 and r.stderr.count("error:") == 1 and message in r.stderr and
          "*MAT_SIMPLIFIED_JOHNSON_COOK" in r.stderr and "model.k:" in r.stderr, r.stderr)

# ---- *MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY (123): strip_pull.k's steel as the modified card,
# the twin's bytes; EPSMAJ and NUMINT against the twin with failure: {thresholds:
# {max_principal_strain}, points}, and EPSTHIN against thinning_strain, elements erode; a plastic
# EPSTHIN and a filtered EPSMAJ refused
STRIP_024 = "*MAT_PIECEWISE_LINEAR_PLASTICITY\n" + STRIP_MAT + "$#       c         p      lcss\n       0.0       0.0         5\n"
assert STRIP_024 in strip_deck
def modified_card(extra):
    return strip_deck.replace(STRIP_024, STRIP_024.replace(
        "*MAT_PIECEWISE_LINEAR_PLASTICITY", "*MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY").replace(
        "         5\n", "         5         0       0.0" + extra + "\n"))
deck_against_twin("modified piecewise linear", os.path.join(WORK, "mat123"),
                  os.path.join(STRIP, "strip_pull_mesh.k"), modified_card(""), strip_twin)
for name, folder, extra, failure in (
        ("EPSMAJ", "mat123_major", "       0.0      0.05         1",
         "{thresholds: {max_principal_strain: 0.05}, points: 1}"),
        ("EPSTHIN", "mat123_thin", "      0.02", "{thresholds: {thinning_strain: 0.02}}")):
    check_erodes(f"modified piecewise linear {name}: the strip's elements erode", deck_against_twin(
        f"modified piecewise linear {name}", os.path.join(WORK, folder),
        os.path.join(STRIP, "strip_pull_mesh.k"), modified_card(extra),
        strip_twin.replace("    poisson_ratio: 0.3\n    flow_curves:",
                           f"    poisson_ratio: 0.3\n    failure: {failure}\n    flow_curves:")))
for name, extra, message in (("plastic EPSTHIN", "     -0.03", "EPSTHIN < 0"),
                             ("filtered EPSMAJ", "       0.0     -0.05", "EPSMAJ < 0")):
    folder = write_case("mat123_bad", modified_card(extra), os.path.join(STRIP, "strip_pull_mesh.k"))
    r = subprocess.run([FPM, "check", os.path.join(folder, "model.k")], capture_output=True, text=True)
    check(f"modified piecewise linear: {name} refused with exit 2 and one sentence naming the card",
          r.returncode == 2 and r.stderr.count("error:") == 1 and message in r.stderr and
          "*MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY" in r.stderr, r.stderr)

# ---- *MAT_024 LCSR (theory.md eq. 7.4-3): strip_pull.k's steel on its slowest curve (LCSS 11)
# with a curve of the yield stress's factor against the strain rate, against the twin with
# flow_curve and rate_scaling; with the table LCSS 5, LCSR is ignored (noted): the table's bytes;
# LCSR beside C, P refused
TWIN_TABLE = ("    flow_curves:\n      - {strain_rate: 0.001, points: [[0, 300.0e6], [0.1, 400.0e6], [0.5, 500.0e6]]}\n"
              "      - {strain_rate: 100, points: [[0, 360.0e6], [0.1, 480.0e6], [0.5, 600.0e6]]}\n")
SLOWEST = "    flow_curve: [[0, 300.0e6], [0.1, 400.0e6], [0.5, 500.0e6]]\n"
assert TWIN_TABLE in strip_twin
RATE_CURVE = "*DEFINE_CURVE\n        99\n                 0.0                 1.0\n" \
             "               100.0                 1.3\n"
def lcsr_deck(fields):
    return strip_deck.replace(STRIP_024, STRIP_024.replace(
        "       0.0       0.0         5\n", fields + "\n")).replace("*END\n", RATE_CURVE + "*END\n")
h_lcsr, h_slow = (deck_against_twin(
    name, os.path.join(WORK, folder), os.path.join(STRIP, "strip_pull_mesh.k"), lcsr_deck(fields),
    strip_twin.replace(TWIN_TABLE, SLOWEST + extra)) for name, folder, fields, extra in (
        ("rate scaling curve", "lcsr", "       0.0       0.0        11        99",
         "    rate_scaling: [[0, 1], [100, 1.3]]\n"),
        ("the slowest curve alone", "lcsr_none", "       0.0       0.0        11", "")))
check("rate scaling curve: it changes the pull (the history differs from the curve alone)",
      h_lcsr is not None and h_slow is not None and read(h_lcsr) != read(h_slow), "")
h_table = deck_against_twin("rate scaling curve beside a table", os.path.join(WORK, "lcsr_table"),
                            os.path.join(STRIP, "strip_pull_mesh.k"),
                            lcsr_deck("       0.0       0.0         5        99"), strip_twin)
r = subprocess.run([FPM, "check", os.path.join(WORK, "lcsr_table", "model.k")], capture_output=True,
                   text=True)
check("rate scaling curve beside a table: noted as ignored",
      r.returncode == 0 and "LCSR ignored" in r.stdout + r.stderr, r.stdout + r.stderr)
folder = write_case("lcsr_bad", lcsr_deck("      40.0       5.0        11        99"),
                    os.path.join(STRIP, "strip_pull_mesh.k"))
r = subprocess.run([FPM, "check", os.path.join(folder, "model.k")], capture_output=True, text=True)
check("rate scaling curve beside C, P: refused with exit 2 and one sentence",
      r.returncode == 2 and r.stderr.count("error:") == 1 and "not both" in r.stderr, r.stderr)

# ---- *MAT_PLASTICITY_WITH_DAMAGE (081) LCSR as *MAT_024's (on the slowest curve LCSS 11): the
# twin with type: plastic_damage and rate_scaling
MAT_081 = ("*MAT_PLASTICITY_WITH_DAMAGE\n"
           "$#     mid        ro         e        pr      sigy      etan      eppf      tdel\n"
           "         1    7850.0   2.1e+11       0.3   3.0e+08       0.0      0.01\n"
           "$#       c         p      lcss      lcsr     eppfr        vp      lcdm    numint\n"
           "       0.0       0.0         5         0      0.03         0         0         1\n")
deck_against_twin(
    "*MAT_081 LCSR", os.path.join(WORK, "mat081_lcsr"), os.path.join(STRIP, "strip_pull_mesh.k"),
    strip_deck.replace(STRIP_024, MAT_081.replace("         5         0      0.03",
                                                "        11        99      0.03")).replace(
        "*END\n", RATE_CURVE + "*END\n"),
    strip_twin.replace("    type: tabulated\n", "    type: plastic_damage\n").replace(
        TWIN_TABLE,
        "    damage: {start: 0.01, rupture: 0.03}\n    failure: {plastic_strain: 0.03, points: 1}\n" +
        SLOWEST + "    rate_scaling: [[0, 1], [100, 1.3]]\n"))

sys.exit(finish())

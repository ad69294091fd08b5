"""LS-DYNA keyword decks' refusals, notes and messages (docs/decks.md), on small decks:
a card fpmshell cannot honour fails with exit 2 and one sentence naming file, line and card; a
card that cannot change the physics gives a note; errors in a card name its line and field, also
inside an *INCLUDE and for values the model reader refuses; other tools' fixed-column habits,
LS-DYNA's forms of initial velocities, walls numbered by place, the older contact forms, rigid
parts held by CMO and NIP left blank read as LS-DYNA reads them.

usage: deck_messages_test.py FPMSHELL WORKDIR
"""
import os
import shutil
import sys

FPM, WORK = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402
import deck_variant  # noqa: E402
from deck_variant import fpmshell, read  # noqa: E402

deck_variant.FPM = FPM


def run(model, out):
    r = fpmshell("run", model, "-o", out, "--quiet", "--threads", "1", "--overwrite")
    return r, os.path.join(out, "history.csv")


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)

# ---- refusals, notes and messages
BASE = """*KEYWORD
*NODE
       1             0.0             0.0             0.0
       2             1.0             0.0             0.0
       3             0.0             1.0             0.0
*ELEMENT_SHELL
       1       1       1       2       3       3
*PART
part
         1         1         1
*SECTION_SHELL
         1         2         0         2
      0.01
*MAT_ELASTIC
         1    7800.0   2.1e+11       0.3
*CONTROL_TERMINATION
     0.001
"""


def deck_case(name, extra, base=BASE, files=None):
    folder = os.path.join(WORK, "cases", name)
    os.makedirs(folder, exist_ok=True)
    for file, text in (files or {}).items():
        with open(os.path.join(folder, file), "w") as f:
            f.write(text)
    path = os.path.join(folder, "deck.k")
    with open(path, "w") as f:
        f.write(base + extra + "*END\n")
    return path, fpmshell("check", path)


def line_of(path, text):
    with open(path) as f:
        for k, line in enumerate(f, 1):
            if line.startswith(text):
                return k
    return -1


path, r = deck_case("valid", "")
check("a minimal deck is valid", r.returncode == 0, r.stderr)

REFUSED = {  # card: what its message must say
    "*MAT_RIGID_DISCRETE\n         2    7800.0   2.1e+11       0.3\n": "this material is not supported",
    "*CONSTRAINED_JOINT_SPHERICAL\n         1         2\n": "this constraint is not supported",
    "*CONSTRAINED_NODAL_RIGID_BODY_INERTIA\n         1\n": "its inertia or constraints would change the model",
    "*CONSTRAINED_GENERALIZED_WELD_FILLET\n         1\n": "reads *CONSTRAINED_GENERALIZED_WELD_SPOT only",
    "*ELEMENT_SOLID\n         1         1         1         2         3\n": "need a *SECTION_SOLID",
    "*ELEMENT_SOLID_ORTHO\n         1         1         1         2         3\n": "not this form of it",
    ("*SECTION_SOLID\n         9         1\n*PART\nsolid\n         9         9         1\n"
     "*ELEMENT_SOLID\n     901       9       1       2       3       4\n"):
        "and solids of rigid parts (*MAT_RIGID)",
    "*SECTION_BEAM\n         1         1\n": "beam, discrete and thick-shell sections",
    "*CONTACT_TIED_SURFACE_TO_SURFACE_FAILURE\n         1         1\n": "the option _FAILURE is not supported",
    "*CONTACT_TIEBREAK_SHELL_EDGE_TO_SURFACE\n         1         1\n": "other tiebreak forms are not supported",
    "*MAT_HONEYCOMB\n         2\n": "this material is not supported",
    "*MAT_ADD_DAMAGE_DIEM\n         1\n": "fpmshell reads *MAT_ADD_DAMAGE_GISSMO, *MAT_ADD_EROSION",
    "*BOUNDARY_PRESCRIBED_MOTION_RIGID_LOCAL\n         1         3         0         1\n": "_LOCAL is not supported",
    "*RIGIDWALL_GEOMETRIC_PRISM\n         0\n": "the option _PRISM is not supported",
    "*FREQUENCY_DOMAIN_SSD\n         1\n": "could change the model",
}
for k, (card, words) in enumerate(REFUSED.items()):
    path, r = deck_case(f"refused{k}", card)
    keyword = card.split("\n")[0]
    where = f"{path}:{line_of(path, keyword)}: {keyword}:"
    check(f"{keyword} is refused with exit 2", r.returncode == 2, r.stdout + r.stderr)
    check(f"{keyword}: the message names file, line and card and says why",
          r.stderr.startswith("error: " + where) and words in r.stderr and
          r.stderr.count("\n") == 1, r.stderr)

# refused at a field: the message names the field's card (the line after the keyword + k)
FIELD_REFUSED = {  # card: (its card with the field, 1 = the first after the keyword; words)
    ("*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC\n         9    7850.0   2.1e+11       0.3"
     "   3.0e+08  -1.0e+08       1.5\n"): (1, "ETAN < 0"),
    ("*MAT_037\n         9    7850.0   2.1e+11       0.3   3.0e+08       0.0       1.5\n"
     "         1\n"): (2, "IDSCALE, EA, COE, ICFLD, STRAINLT"),
    "*CONTROL_RIGID\n         0         0         0         0         0         1         0         1\n":
        (1, "RBSMS"),
    ("*INITIAL_VELOCITY_NODE\n         1       0.0       0.0       1.0       0.0       0.0"
     "       0.0         9\n"): (1, "ICID 9: no *DEFINE_COORDINATE_SYSTEM or _VECTOR defines it"),
    ("*INITIAL_VELOCITY_NODE\n         1       0.0       0.0       1.0       0.0       0.0"
     "       0.0         9\n*DEFINE_COORDINATE_NODES\n         9         1         2         3\n"):
        (1, "*DEFINE_COORDINATE_NODES (axes from node positions) is not supported here"),
}
for k, (card, (offset, words)) in enumerate(FIELD_REFUSED.items()):
    path, r = deck_case(f"field_refused{k}", card)
    keyword = card.split("\n")[0]
    where = f"{path}:{line_of(path, keyword) + offset}: {keyword}:"
    check(f"{keyword} ({words}) is refused with exit 2", r.returncode == 2, r.stdout + r.stderr)
    check(f"{keyword} ({words}): the message names file, the field's line and card",
          r.stderr.startswith("error: " + where) and words in r.stderr and
          r.stderr.count("\n") == 1, r.stderr)

NOTED = ["*CONTROL_HOURGLASS\n         1\n", "*HOURGLASS\n         1\n",
         "*SENSOR_DEFINE_NODE\n         1\n", "*EOS_GRUNEISEN\n         1\n",
         "*KEYWORD_ID\nmodel_2024  06-12-2026\n", "*CONTROL_UNITS\n         m        kg         s\n",
         "*CONTROL_ADAPTIVE\n2.50000E-4       5.0         2         3\n",
         "*CONTROL_ADAPSTEP\n       1.0      0.01\n",
         "*CONTROL_RIGID\n         0         0         0         0         0         1\n",
         "*INTERFACE_SPRINGBACK_LSDYNA\n        11       100\n"]
for k, card in enumerate(NOTED):
    path, r = deck_case(f"noted{k}", card)
    keyword = card.split("\n")[0]
    check(f"{keyword} is ignored with a note",
          r.returncode == 0 and f"note: {path}:{line_of(path, keyword)}: {keyword}: ignored" in r.stdout,
          r.stdout + r.stderr)

ERRORS = [  # (name, extra cards, other files, the line's start, words of the message)
    ("bad number", "*INITIAL_VELOCITY\n         0\n       1.0      abc\n", None,
     "       1.0      abc", "VY 'abc' is not a finite number"),
    ("undefined parameter", "*INITIAL_VELOCITY\n         0\n     &fast\n", None, "     &fast",
     "parameter 'FAST' is not defined"),
    ("undefined set", "*BOUNDARY_SPC_SET\n         4         0         1\n", None,
     "         4         0         1", "no *SET_NODE_LIST defines set 4"),
    ("friction", "*RIGIDWALL_PLANAR\n         0\n       0.0       0.0      -1.0       0.0       0.0       0.0       1.5\n",
     None, "       0.0       0.0      -1.0", "FRIC must be from 0 to 1"),
    ("value the model refuses", "*MAT_ELASTIC\n         2    7800.0   2.1e+11       0.7\n"
     "*PART\nsecond\n         2         1         2\n*ELEMENT_SHELL\n       2       2       1       2       3       3\n",
     None, "         2    7800.0   2.1e+11       0.7",
     "*MAT_ELASTIC (model key 'materials.mat_2.poisson_ratio'): must be greater than -1"),
    ("include", "*INCLUDE\nmore.k\n", {"more.k": "*KEYWORD\n*CONTROL_TIMESTEP\n       0.0      zero\n*END\n"},
     None, "more.k:3: *CONTROL_TIMESTEP: TSSFAC 'zero' is not a finite number"),
    ("include cycle", "*INCLUDE\nloop.k\n", {"loop.k": "*INCLUDE\nloop.k\n"}, None, "includes itself"),
    ("missing include", "*INCLUDE\nabsent.k\n", None, "absent.k", "cannot open"),
    ("weld of one node", "*CONSTRAINED_SPOTWELD\n         3         3\n", None,
     "         3         3", "N1 and N2 are the same node 3"),
    ("set defined twice", "*SET_NODE_LIST\n         9\n         1\n*SET_NODE_LIST\n         9       0.0\n         2\n",
     None, "         9       0.0", "*SET_NODE 9 is defined twice (first at "),
    ("part defined twice", "*PART\nagain\n         1         1         1         0\n", None,
     "         1         1         1         0", "part 1 is defined twice (first at "),
    ("material defined twice", "*MAT_ELASTIC\n         1    2700.0     7e+10      0.33\n", None,
     "         1    2700.0", "material 1 is defined twice (first at "),
    ("wall motion", "*RIGIDWALL_GEOMETRIC_SPHERE_MOTION\n         0\n       0.0       0.0      -5.0\n"
     "       1.0\n         3         0       0.0       0.0       1.0\n*DEFINE_CURVE\n         3\n"
     "                 0.0                 0.0\n                 1.0                 2.0\n", None,
     "         3         0       0.0", "is not a constant velocity"),
]
for name, extra, files, start, words in ERRORS:
    path, r = deck_case(name.replace(" ", "_"), extra, files=files)
    where = f"{path}:{line_of(path, start)}:" if start else ""
    check(f"{name}: exit 2, one sentence", r.returncode == 2 and r.stderr.count("\n") == 1,
          r.stdout + r.stderr)
    check(f"{name}: the message names the place and says what", words in r.stderr and
          (not where or r.stderr.startswith("error: " + where)), r.stderr)
    if "defined twice" in words:
        check(f"{name}: the message names the first definition's place too",
              (words + path + ":") in r.stderr, r.stderr)

# a surface-to-surface contact between two parts: self-contact over both
two_parts = BASE.replace("*ELEMENT_SHELL\n       1       1       1       2       3       3\n",
                         "*NODE\n       4             1.0             1.0             0.0\n"
                         "*ELEMENT_SHELL\n       1       1       1       2       3       3\n"
                         "       2       2       2       4       3       3\n"
                         "*PART\nother\n         2         1         1\n")
path, r = deck_case("surface to surface", "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID\n"
                    "         1 s2s\n         1         2         3         3\n", base=two_parts)
check("surface to surface: self-contact over both parts", r.returncode == 0 and
      "contact self over 2 elements" in r.stdout and "over both sides together" in r.stdout,
      r.stdout + r.stderr)
# a node set as the slave side of a nodes-to-surface contact: those nodes against the faces
path, r = deck_case("nodes to surface", "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n"
                    "         1         2         4         3\n"
                    "*SET_NODE_LIST\n         1\n         1         2         3\n", base=two_parts)
check("nodes to surface with a node set: the set's particles against part 2's faces",
      r.returncode == 0 and "contact self over 1 elements" in r.stdout and
      "the node set's particles against the master side's faces" in r.stdout, r.stdout + r.stderr)
converted = os.path.join(os.path.dirname(path), "converted.yaml")
fpmshell("convert", path, "-o", converted)
check("nodes to surface with a node set: converted as `nodes` of the self-contact",
      os.path.exists(converted) and "{type: self, elements: part_2, nodes: node_set_1}" in read(converted),
      read(converted) if os.path.exists(converted) else "no file")
# ICOMP 1: a material angle per point (a third card), which isotropic laws do not need: noted
SECTION = "*SECTION_SHELL\n         1         2         0         2\n      0.01\n"
assert SECTION in BASE
angled = BASE.replace(SECTION, "*SECTION_SHELL\n         1         2       0.0         2       0.0         0"
                      "         1\n      0.01\n       0.0      45.0\n")
path, r = deck_case("angles", "", base=angled)
check("ICOMP 1: the angles noted as changing nothing", r.returncode == 0 and "ICOMP 1" in r.stdout,
      r.stdout + r.stderr)
path, r = deck_case("angles 2", "", base=angled.replace("         0         1\n      0.01",
                                                         "         0         2\n      0.01"))
check("ICOMP 2: refused", r.returncode == 2 and "ICOMP must be 0 or 1" in r.stderr, r.stderr)

# *CONTROL_SHELL NFAIL1 1 (LS-DYNA deletes distorted quadrilaterals): a note of what fpmshell does
path, r = deck_case("nfail", "*CONTROL_SHELL\n        20         0        -1         0\n"
                    "       0.0         0         0         0         0         1         1\n")
check("*CONTROL_SHELL NFAIL1: noted as not read, saying what happens instead",
      r.returncode == 0 and "NFAIL1, NFAIL4 not read" in r.stdout, r.stdout + r.stderr)

# a segment set as a side (SSTYP 0): the shells its segments cover
path, r = deck_case("segment side", "*CONTACT_ERODING_SURFACE_TO_SURFACE\n"
                    "         1         1         0         3\n\n\n         0         1         0\n"
                    "*SET_SEGMENT\n         1\n         2         4         3         3\n", base=two_parts)
check("a segment set as a contact's side: the shells it covers, with the other side",
      r.returncode == 0 and "contact self over 2 elements" in r.stdout, r.stdout + r.stderr)
converted = os.path.join(os.path.dirname(path), "converted.yaml")
fpmshell("convert", path, "-o", converted)
check("a segment set as a contact's side: converted as the element set of its shells",
      os.path.exists(converted) and "contact_segments_1: {element_ids: [2]}" in read(converted)
      and "elements: [contact_segments_1, part_1]" in read(converted),
      read(converted) if os.path.exists(converted) else "no file")
path, r = deck_case("segment side of no shell", "*CONTACT_AUTOMATIC_SINGLE_SURFACE\n"
                    "         1         0         0\n*SET_SEGMENT\n         1\n"
                    "         1         2         4         4\n", base=two_parts)
check("a contact's segment that covers no shell: refused naming the segment",
      r.returncode == 2 and "no shell element has the nodes of this segment" in r.stderr, r.stderr)
path, r = deck_case("surface to surface of a node set", "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n"
                    "         1         2         4         3\n"
                    "*SET_NODE_LIST\n         1\n         1         2         3\n", base=two_parts)
check("surface to surface with a node set: refused", r.returncode == 2 and "SSTYP 4" in r.stderr
      and "nodes-to-surface" in r.stderr, r.stderr)

# the fixed-column habits of decks written by other tools give BASE's model: lower-case
# keywords, a blank line inside a block (a part's blank heading: a card of defaults) and between
# records, NIP left blank, reals without an E (1.0000-2), integers written as reals (1.0), fields
# that run together (read by column, never by blanks)
QUIRKS = """*keyword
*node
       1             0.0             0.0             0.0
       2        1.0000+0             0.0             0.0

       3             0.0   1.00000000000             0.0
*element_shell
       1       1       1       2       3       3
*part

         1         1         1
*section_shell
         1         2         0
  1.0000-2
*mat_elastic
       1.07800.000002.1000E+11       0.3
*control_termination
  1.0000-3

"""


def summary(r):
    return [l for l in r.stdout.splitlines() if not l.startswith(("model", "title", "note"))]


_, plain = deck_case("plain", "")
_, quirky = deck_case("quirks", "", base=QUIRKS)
check("a deck in other tools' fixed-column habits gives the plain deck's model",
      plain.returncode == 0 and quirky.returncode == 0 and summary(plain) == summary(quirky),
      quirky.stdout + quirky.stderr)

# initial velocities in LS-DYNA's forms: a node of its own (*INITIAL_VELOCITY_NODE, given
# first) keeps its velocity over *INITIAL_VELOCITY of all nodes, whose exempted set (NSIDEX)
# takes the velocities of the third card
VELOCITIES = BASE.replace("     0.001\n", "    1.0e-6\n") + """*INITIAL_VELOCITY_NODE
         1       7.0       0.0       0.0
*DATABASE_NODOUT
    1.0e-7
*DATABASE_HISTORY_NODE
         1         2         3
*INITIAL_VELOCITY
         0         9
       5.0       0.0       0.0
       3.0       0.0       0.0
*SET_NODE_LIST
         9
         1         2
"""
path, r = deck_case("initial velocities", "", base=VELOCITIES)
out = os.path.join(os.path.dirname(path), "results")
r, h = run(path, out)
rows = read(h).splitlines() if r.returncode == 0 else ["", ""]
first = dict(zip(rows[0].split(","), rows[1].split(",")))
check("initial velocities: _NODE over the set, NSIDEX's own velocity, the rest",
      r.returncode == 0 and [first.get(f"node{n}_vx") for n in (1, 2, 3)] == ["7", "3", "5"],
      r.stderr + str(rows[:2]))

# walls without _ID are numbered by their place in the deck (LS-DYNA's rule), although the
# translator takes them in the order of their text: the first wall here sorts last
path, r = deck_case("walls numbered by place", "*RIGIDWALL_PLANAR\n         0\n"
                    "       0.0       0.0      -2.0       0.0       0.0       0.0\n"
                    "*RIGIDWALL_PLANAR\n         0\n"
                    "       0.0       0.0      -1.0       0.0       0.0       0.0\n")
converted = os.path.join(os.path.dirname(path), "walls.yaml")
c = fpmshell("convert", path, "-o", converted)
walls = [l for l in read(converted).splitlines() if "name: rigidwall" in l] if c.returncode == 0 else []
check("walls without _ID: numbered by their place in the deck", len(walls) == 2 and
      "name: rigidwall1, shape: plane, point: [0, 0, -2]" in walls[1] + walls[0] and
      "name: rigidwall2, shape: plane, point: [0, 0, -1]" in walls[1] + walls[0], c.stderr + str(walls))

# the older and other forms of the contacts fpmshell has: each as its self-contact, with a note
# where the mapping is not one-to-one
# (single-surface forms over part 1 alone, two-sided ones over parts 1 and 2)
for keyword, words, count in [("*CONTACT_SINGLE_SURFACE", "the older single-surface contact", 1),
                              ("*CONTACT_SURFACE_TO_SURFACE", "a one-sided contact", 2),
                              ("*CONTACT_NODES_TO_SURFACE", "a one-sided contact", 2),
                              ("*CONTACT_AUTOMATIC_GENERAL", "general contact", 1),
                              ("*CONTACT_AUTOMATIC_SINGLE_SURFACE_MORTAR", "_MORTAR", 1),
                              ("*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE", "a forming contact", 2),
                              ("*CONTACT_FORMING_SURFACE_TO_SURFACE_ID", "a forming contact", 2)]:
    cid = "         7\n" if keyword.endswith("_ID") else ""
    path, r = deck_case(keyword[1:].lower(), keyword + "\n" + cid + "         1         2         3         3\n",
                        base=two_parts)
    check(f"{keyword}: read as the self-contact with a note", r.returncode == 0 and
          f"contact self over {count} elements" in r.stdout and words in r.stdout,
          r.stdout + r.stderr)

# nodes standing on a planar wall (a car's wheels on the ground): LS-DYNA's wall acts on the
# nodes themselves, so the shell's thickness puts none of them inside it
path, r = deck_case("standing on the wall", "*RIGIDWALL_PLANAR\n         0\n"
                    "       0.0       0.0       0.0       0.0       0.0       1.0\n")
check("nodes lying on a planar wall: the deck runs as it is", r.returncode == 0, r.stdout + r.stderr)

# a rigid part held as *MAT_RIGID's CMO = 1 says: CON1 4 (x and y), CON2 7 (every rotation)
held = two_parts.replace("*PART\nother\n         2         1         1\n",
                         "*PART\nother\n         2         1         2\n*MAT_RIGID\n"
                         "         2    7800.0   2.1e+11       0.3\n       1.0       4.0       7.0\n")
path, r = deck_case("rigid held", "", base=held)
converted = os.path.join(os.path.dirname(path), "held.yaml")
c = fpmshell("convert", path, "-o", converted)
check("*MAT_RIGID CMO 1: the fixed components as the material's fix", c.returncode == 0 and
      "fix: [ux, uy, rx, ry, rz]" in read(converted), c.stderr)
path, r = deck_case("rigid local", "", base=held.replace("       1.0       4.0       7.0\n",
                                                          "      -1.0         3    111000\n"))
check("*MAT_RIGID CMO -1 (a local system): refused in one sentence", r.returncode == 2 and
      "CMO -1" in r.stderr and r.stderr.count("\n") == 1, r.stderr)

# a plastic section with NIP left blank: LS-DYNA's default, two Gauss points, read as it is
plastic = BASE.replace("*SECTION_SHELL\n         1         2         0         2\n",
                       "*SECTION_SHELL\n         1         2\n").replace(
    "*MAT_ELASTIC\n         1    7800.0   2.1e+11       0.3\n",
    "*MAT_PLASTIC_KINEMATIC\n         1    7800.0   2.1e+11       0.3   2.5e+08   1.0e+09\n")
assert plastic != BASE
path, r = deck_case("plastic nip blank", "", base=plastic)
check("a plastic section with NIP blank: two Gauss points, noted", r.returncode == 0 and
      "2 Gauss x 3 points" in r.stdout and "two Gauss points, as LS-DYNA integrates it" in r.stdout,
      r.stdout + r.stderr)

# a node set, in an included file, that lists a node of no shell and no mass: left out of the
# set with a note naming the included file and the set's line (the run goes on)
sets = ("*KEYWORD\n*NODE\n       9             5.0             5.0             0.0\n"
        "*SET_NODE_LIST\n         7\n         1         9\n*END\n")
path, r = deck_case("massless set node", "*INCLUDE\nsets.k\n", files={"sets.k": sets})
included = os.path.join(os.path.dirname(path), "sets.k")
check("a set's node of no shell and no mass: left out, noted at the set's file and line",
      r.returncode == 0 and f"note: {included}:{line_of(included, '         7')}: the node set "
      "'node_set_7' lists 1 node (9) on no shell and without a point mass" in r.stdout,
      r.stdout + r.stderr)

path, r = deck_case("no termination", "", base=BASE.replace("*CONTROL_TERMINATION\n     0.001\n", ""))
check("a deck without *CONTROL_TERMINATION is refused", r.returncode == 2 and
      "CONTROL_TERMINATION" in r.stderr, r.stderr)

# *CONTROL_TERMINATION DTMIN with *CONTROL_TIMESTEP ERODE: a floor of DTMIN times the first
# step; shells erode below it with ERODE 10, 11, 110, 111, the run stops there with the others
for erode, words in (("11", "{factor: 0.01, erode: true}"), ("1", "{factor: 0.01}"),
                     ("0", "{factor: 0.01}")):
    path, r = deck_case(f"dtmin erode {erode}", "*CONTROL_TIMESTEP\n       0.0       0.9"
                        "         0       0.0       0.0         0" + erode.rjust(10) + "\n",
                        base=BASE.replace("     0.001\n", "     0.001         0      0.01\n"))
    converted = os.path.join(os.path.dirname(path), "dtmin.yaml")
    c = fpmshell("convert", path, "-o", converted)
    lines = [l.strip() for l in read(converted).splitlines()] if c.returncode == 0 else []
    check(f"DTMIN 0.01 with ERODE {erode}: control.minimum_time_step: {words}",
          r.returncode == 0 and f"minimum_time_step: {words}" in lines, c.stderr + str(lines))
    check(f"DTMIN 0.01 with ERODE {erode}: fpmshell check prints the floor", "minimum time step "
          in r.stdout and ("falls below it erode" if erode == "11" else "the run stops if")
          in r.stdout, r.stdout)
path, r = deck_case("ms1st", "*CONTROL_TIMESTEP\n       0.0       0.9         0       0.0"
                    "   -1.0e-6         0         0         1\n")
converted = os.path.join(os.path.dirname(path), "ms1st.yaml")
c = fpmshell("convert", path, "-o", converted)
lines = [l.strip() for l in read(converted).splitlines()] if c.returncode == 0 else []
check("DT2MS < 0 with MS1ST 1: mass scaling at set-up only", r.returncode == 0 and
      "mass_scaling: {time_step: 9e-07, during_run: false}" in lines, c.stderr + str(lines))
for name, card_2, words in (("dt2msf", "      0.05", "DT2MSF (mass scaling to a factor"),
                             ("dt2mslc", "       0.0         7", "DT2MSLC (a curve"),
                             ("imscl", "       0.0         0         3", "IMSCL (selective")):
    path, r = deck_case(name, "*CONTROL_TIMESTEP\n       0.0       0.9\n" + card_2 + "\n")
    check(f"*CONTROL_TIMESTEP {name.upper()}: refused, naming card 2's line", r.returncode == 2
          and f"{path}:{line_of(path, '*CONTROL_TIMESTEP') + 2}: *CONTROL_TIMESTEP: {words}"
          in r.stderr, r.stderr)
path, r = deck_case("dtmin one", "", base=BASE.replace("     0.001\n", "     0.001         0       1.0\n"))
check("DTMIN 1: refused, naming the card and the field", r.returncode == 2 and
      "*CONTROL_TERMINATION" in r.stderr and "DTMIN must be in [0, 1)" in r.stderr, r.stderr)
path, r = deck_case("erode five", "*CONTROL_TIMESTEP\n       0.0       0.9         0       0.0"
                    "       0.0         0         5\n")
check("ERODE 5: refused, naming the card and the field", r.returncode == 2 and
      "*CONTROL_TIMESTEP" in r.stderr and "ERODE must be" in r.stderr, r.stderr)

sys.exit(finish())

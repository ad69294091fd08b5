"""What the deck scripts against YAML twins (deck_test.py, deck_material_test.py) share: running
fpmshell, reading, writing a variant beside its mesh, the check that a deck and its twin give
the same history.csv, and that a run eroded. start() sets the program and the work folder."""
import json
import os
import shutil
import subprocess

from check_tally import check

FPM = None  # the fpmshell program and the scripts' work folder, set by start
WORK = None


def start(argv):
    """`SCRIPT FPMSHELL WORKDIR`: sets FPM and WORK and empties WORK; returns (FPM, WORK)."""
    global FPM, WORK
    FPM, WORK = argv[1], argv[2]
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    return FPM, WORK


def fpmshell(*args):
    return subprocess.run([FPM, *args], capture_output=True, text=True, timeout=600)


def run(model, out):
    r = fpmshell("run", model, "-o", out, "--quiet", "--threads", "1", "--overwrite")
    return r, os.path.join(out, "history.csv")


def read(path):
    with open(path) as f:
        return f.read()


def check_erodes(name, history):
    """The run whose history.csv is `history` (None: it failed) eroded some element."""
    if history is None:
        return
    with open(os.path.join(os.path.dirname(history), "summary.json")) as f:
        eroded = json.load(f).get("eroded_elements", 0)
    check(name, eroded > 0, eroded)


def write_case(name, text, mesh):
    """Writes `text` as WORK/name/model.k beside a copy of the mesh file; returns the folder."""
    folder = os.path.join(WORK, name)
    os.makedirs(folder, exist_ok=True)
    shutil.copy(mesh, folder)
    with open(os.path.join(folder, "model.k"), "w") as f:
        f.write(text)
    return folder


def deck_against_twin(name, folder, mesh, deck_text, twin_text):
    """Writes a variant of a test deck and of its twin into `folder` beside their mesh, runs
    both and checks that they give the same history.csv; returns the deck's history file, or
    None when a run failed."""
    os.makedirs(folder, exist_ok=True)
    shutil.copy(mesh, folder)
    with open(os.path.join(folder, "model.k"), "w") as f:
        f.write(deck_text)
    with open(os.path.join(folder, "model.yaml"), "w") as f:
        f.write(twin_text)
    r_deck, h_deck = run(os.path.join(folder, "model.k"), os.path.join(folder, "deck"))
    r_twin, h_twin = run(os.path.join(folder, "model.yaml"), os.path.join(folder, "twin"))
    check(f"{name}: deck and twin run", r_deck.returncode == 0 and r_twin.returncode == 0,
          r_deck.stderr + r_twin.stderr)
    if r_deck.returncode or r_twin.returncode:
        return None
    check(f"{name}: the same history.csv", read(h_deck) == read(h_twin), "the files differ")
    return h_deck

"""What the deck scripts (tests/io/deck_rules_test.py, deck_rigid_test.py) share: running
fpmshell, writing a variant of a test deck or twin beside its mesh, running a model into a folder
beside it, and the check that a deck and its twin give the same history.csv bytes."""
import os
import shutil
import subprocess

from check_tally import check

FPM = None  # the fpmshell program: each script sets it from its arguments


def fpmshell(*args):
    return subprocess.run([FPM, *args], capture_output=True, text=True, timeout=600)


def read(path):
    with open(path) as f:
        return f.read()


def write(folder, name, text, mesh):
    """Writes `text` as folder/name beside a copy of the mesh file `mesh`; returns its path."""
    os.makedirs(folder, exist_ok=True)
    shutil.copy(mesh, folder)
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def run(model):
    """Runs `model` on one thread into out_<extension> beside it: (result, history.csv path)."""
    out = os.path.join(os.path.dirname(model), "out_" + os.path.basename(model).split(".")[1])
    r = fpmshell("run", model, "-o", out, "--quiet", "--threads", "1", "--overwrite")
    return r, os.path.join(out, "history.csv")


def twin_pair(name, deck_path, twin_path):
    """Runs a deck and its twin and checks that both run and give the same history.csv; returns
    the deck's history text, or None when a run failed."""
    r_deck, h_deck = run(deck_path)
    r_twin, h_twin = run(twin_path)
    check(f"{name}: deck and twin run", r_deck.returncode == 0 and r_twin.returncode == 0,
          r_deck.stderr + r_twin.stderr)
    if r_deck.returncode or r_twin.returncode:
        return None
    check(f"{name}: the same history.csv", read(h_deck) == read(h_twin), "the files differ")
    return read(h_deck)

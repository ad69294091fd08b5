"""What the deck scripts (tests/io/deck_rules_test.py, deck_rigid_test.py, ...) share: their start
on a test deck of examples/decks, running fpmshell, writing a variant of a test deck or twin
beside its mesh, running a model into a folder beside it, and the check that a deck and its twin
give the same history.csv bytes."""
import os
import shutil
import subprocess

from check_tally import check

FPM = None  # the fpmshell program: start sets it from the script's arguments
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def start(argv, example):
    """The start of a script `SCRIPT FPMSHELL WORKDIR` on the test deck examples/decks/<example>:
    sets FPM, empties WORKDIR; returns (WORKDIR, the example's folder, its deck's and its twin's
    text, write), write(folder, name, text, mesh=<example>_mesh.k) writing beside a copy of a
    mesh file."""
    global FPM
    FPM, work = argv[1], argv[2]
    folder = os.path.join(ROOT, "examples", "decks", example)
    mesh_file = os.path.join(folder, example + "_mesh.k")

    def write_variant(where, name, text, mesh=mesh_file):
        return write(where, name, text, mesh)

    shutil.rmtree(work, ignore_errors=True)
    return (work, folder, read(os.path.join(folder, example + ".k")),
            read(os.path.join(folder, example + ".yaml")), write_variant)


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


def write_files(folder, files):
    """Writes {name: text} into folder (made if missing); returns the folder."""
    os.makedirs(folder, exist_ok=True)
    for name, text in files.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    return folder


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

"""Card order is free (docs/decks.md): LS-DYNA reads a deck as a whole, so a card may
refer to a part, set, curve, material or section defined anywhere, before or after it, in any
included file. Every test deck of examples/decks is written again

- with its keyword blocks reversed,
- shuffled (three seeds),
- shuffled and spread over nested *INCLUDE files (some in a sub-folder, each including the
  next),

and each version must give the model the original gives (the same `fpmshell convert` text,
comments aside) and the same history.csv bytes.

A block is a keyword and its data cards, moved as a whole; a *DEFINE_TABLE moves with the
*DEFINE_CURVE cards that follow it (they are its curves, by LS-DYNA's rule); a long *NODE or
*ELEMENT_SHELL block is cut into three blocks first, so that nodes and shells come in another
order too. *KEYWORD stays first and *END is dropped.

usage: deck_order_test.py FPMSHELL WORKDIR
"""
import os
import random
import shutil
import subprocess
import sys

FPM, WORK = sys.argv[1], sys.argv[2]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECKS = os.path.join(ROOT, "examples", "decks")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402


def inline(path):
    """The lines of the deck at `path` with every *INCLUDE replaced by the file it names."""
    out = []
    lines = open(path).read().splitlines()
    k = 0
    while k < len(lines):
        line = lines[k]
        if line.strip().upper() == "*INCLUDE":
            # every file name up to the next keyword (an *INCLUDE may list several)
            while k + 1 < len(lines) and not lines[k + 1].startswith("*"):
                k += 1
                if lines[k].strip() and not lines[k].startswith("$"):
                    out += inline(os.path.join(os.path.dirname(path), lines[k].strip()))
        else:
            out.append(line)
        k += 1
    return out


def keyword(unit):
    return unit[0].strip().upper()


def blocks(lines):
    """The keyword blocks of a deck's lines (comments before the first keyword dropped); a
    *DEFINE_TABLE and the *DEFINE_CURVE blocks that follow it are one block."""
    units = []
    for line in lines:
        if line.startswith("*"):
            units.append([line])
        elif units:
            units[-1].append(line)
    merged = []
    for u in units:
        if keyword(u) in ("*KEYWORD", "*END"):
            continue
        if keyword(u).startswith("*DEFINE_CURVE") and merged and keyword(merged[-1]).startswith("*DEFINE_TABLE"):
            merged[-1] = merged[-1] + u
        elif keyword(u) in ("*NODE", "*ELEMENT_SHELL") and len(u) > 7:
            # a long block as three blocks of the same keyword, which then move apart
            cards = [line for line in u[1:] if not line.startswith("$")]
            third = (len(cards) + 2) // 3
            merged += [[u[0]] + cards[k:k + third] for k in range(0, len(cards), third)]
        else:
            merged.append(u)
    return merged


def write_deck(folder, name, units, spread=0):
    """Writes NAME.k in `folder`; with spread > 0 the units go over 1 + spread files, the main
    one including the first, each including the next, every other one in a sub-folder."""
    os.makedirs(folder, exist_ok=True)
    chunks = [units] if spread == 0 else [units[k::spread + 1] for k in range(spread + 1)]
    paths = [os.path.join(folder, name + ".k")]
    for k in range(1, len(chunks)):
        sub = "inc" if k % 2 else "."
        paths.append(os.path.join(os.path.dirname(paths[k - 1]), sub, f"part{k}.k"))
    for k, chunk in enumerate(chunks):
        os.makedirs(os.path.dirname(paths[k]), exist_ok=True)
        text = ["*KEYWORD"] if k == 0 else ["$ part %d of %s" % (k, name)]
        half = len(chunk) // 2
        for u in chunk[:half]:
            text += u
        if k + 1 < len(chunks):  # the next file, named relative to this one, in the middle
            text += ["*INCLUDE", os.path.relpath(paths[k + 1], os.path.dirname(paths[k]))]
        for u in chunk[half:]:
            text += u
        if k == 0:
            text.append("*END")
        with open(paths[k], "w") as f:
            f.write("\n".join(text) + "\n")
    return paths[0]


def model_text(deck):
    """The model `fpmshell convert` writes for a deck, its comments and mesh line left out."""
    out = os.path.join(os.path.dirname(deck), "converted.yaml")
    r = subprocess.run([FPM, "convert", deck, "-o", out, "--overwrite"], capture_output=True,
                       text=True, timeout=300)
    if r.returncode != 0:
        return "convert failed: " + r.stderr
    return "\n".join(l for l in open(out).read().splitlines()
                     if not l.startswith("#") and not l.startswith("mesh:"))


def history(deck, out):
    r = subprocess.run([FPM, "run", deck, "-o", out, "--quiet", "--threads", "1", "--overwrite"],
                       capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        return "run failed: " + r.stderr
    return open(os.path.join(out, "history.csv")).read()


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
for name in sorted(d for d in os.listdir(DECKS) if os.path.isdir(os.path.join(DECKS, d))):
    original = os.path.join(DECKS, name, name + ".k")
    # the original, inlined into one file first (the same cards in their own order)
    units = blocks(inline(original))
    base = write_deck(os.path.join(WORK, name, "inline"), name, units)
    reference_model = model_text(base)
    reference_history = history(base, os.path.join(WORK, name, "inline_results"))
    check(f"{name}: the inlined deck runs", not reference_history.startswith("run failed"),
          reference_history)
    check(f"{name}: the inlined deck gives the original's history",
          reference_history == history(original, os.path.join(WORK, name, "original_results")))
    rng = random.Random(20261206)
    variants = {"reversed": (list(reversed(units)), 0)}
    for seed in range(3):
        shuffled = units[:]
        rng.shuffle(shuffled)
        variants[f"shuffled_{seed}"] = (shuffled, 0)
    spread = units[:]
    rng.shuffle(spread)
    variants["shuffled_in_nested_includes"] = (spread, 3)
    for variant, (order, files) in variants.items():
        deck = write_deck(os.path.join(WORK, name, variant), name, order, files)
        model = model_text(deck)
        check(f"{name} {variant}: the same model", model == reference_model,
              model if model.startswith("convert failed") else "the translated models differ")
        h = history(deck, os.path.join(WORK, name, variant + "_results"))
        check(f"{name} {variant}: the same history.csv bytes", h == reference_history,
              h if h.startswith("run failed") else "the files differ")

sys.exit(finish())

#!/usr/bin/env python3
"""Runs the public LS-DYNA decks of tools/deck_corpus.json as they are and writes docs/deck-corpus.md.

Each deck is laid out from a local mirror of its repository (nothing of it is committed here):
MIRRORS/<owner>+<name>/repo, a git repository holding the deck's commit (the search tool's
`fetch github:<owner>/<name>` makes one under /work/.mirror; a `git clone` works as well when
given as --mirrors). For each deck the script

- writes its files into WORK/<name>/ (`git show COMMIT:PATH`, the repository's layout kept, so
  that its includes are found),
- runs `fpmshell check` on it, and when that passes `fpmshell run` (to the deck's end time, or
  --end-time when given, at most --timeout seconds),
- records the elements, the result (ran; refused, with the one sentence; failed, with why) and
  the wall time, and whether that is what the deck's scope asks: a deck of shells (and rigid
  solids) must run, any other must be refused with exit 2 and one sentence naming file, line
  and card.

usage: tools/deck_corpus.py [--fpmshell build/fpmshell] [--mirrors /work/.mirror]
                            [--work build/deck_corpus] [--output docs/deck-corpus.md]
                            [--end-time T] [--timeout S] [--only NAME ...]
                            [--ranks N [--mpiexec mpirun]]
With --ranks, every deck that ran runs again on N ranks (`mpirun -np N`, one thread each), whose
history.csv and energy.csv must be the same bytes as the single process's (a column of the table).
Exits 1 when a deck's result is not what its scope asks, or differs on N ranks (the table is
written all the same).
"""
import argparse
import datetime
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def lay_out(deck, mirrors, work):
    """Writes the deck's files into work/<name>; returns the main deck's path, or raises
    RuntimeError saying what is missing."""
    repo = os.path.join(mirrors, deck["repo"].replace("/", "+"), "repo")
    if not os.path.isdir(repo):
        raise RuntimeError("no mirror of %s at %s (fetch github:%s)" % (deck["repo"], repo, deck["repo"]))
    folder = os.path.join(work, deck["name"])
    paths = []
    for path in deck["files"]:
        p = subprocess.run(["git", "-C", repo, "show", "%s:%s" % (deck["commit"], path)],
                           capture_output=True)
        if p.returncode != 0:
            raise RuntimeError("%s:%s not in the mirror: %s" % (deck["commit"], path,
                                                                p.stderr.decode(errors="replace").strip()))
        target = os.path.join(folder, path)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "wb") as f:
            f.write(p.stdout)
        paths.append(target)
    return paths[0]


def one_sentence_refusal(code, text, deck_path):
    """Whether a run's output is a refusal as promised: exit 2 and one error line naming a file
    of the deck, a line number and a card."""
    errors = [l for l in text.splitlines() if l.startswith("error:")]
    return (code == 2 and len(errors) == 1 and
            re.match(r"error: .+:\d+: \*[A-Z_]+", errors[0]) is not None), errors[0] if errors else ""


def run_deck(fpm, deck_path, end_time, timeout):
    """(result, detail, elements, wall seconds)."""
    check = subprocess.run([fpm, "check", deck_path], capture_output=True, text=True, timeout=600)
    out = check.stdout + check.stderr
    m = re.search(r"^elements\s+(\d+)", check.stdout, re.M)
    elements = int(m.group(1)) if m else None
    if check.returncode != 0:
        ok, sentence = one_sentence_refusal(check.returncode, out, deck_path)
        return ("refused" if ok else "failed"), (sentence or out.strip()[-300:]), elements, 0.0
    args = [fpm, "run", deck_path, "-o", os.path.join(os.path.dirname(deck_path), "results"),
            "--quiet", "--overwrite"]
    if end_time:
        args += ["--set", "control.end_time=%g" % end_time]
    t0 = time.time()
    try:
        r = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "stopped", "still running after %d s" % timeout, elements, time.time() - t0
    wall = time.time() - t0
    if r.returncode == 0:
        return "ran", "", elements, wall
    errors = [l for l in (r.stdout + r.stderr).splitlines() if l.startswith("error")]
    return "failed", "exit %d: %s" % (r.returncode, errors[0] if errors else (r.stdout + r.stderr)[-300:]), elements, wall


def same_on_ranks(fpm, mpiexec, ranks, deck_path, end_time, timeout):
    """Runs the deck on `ranks` ranks beside its single-process results; (whether its
    history.csv and energy.csv are the same bytes, what the table says)."""
    folder = os.path.dirname(deck_path)
    out = os.path.join(folder, "results_%d_ranks" % ranks)
    args = [mpiexec, "-np", str(ranks), "--oversubscribe", fpm, "run", deck_path, "-o", out,
            "--quiet", "--overwrite", "--threads", "1"]
    if end_time:
        args += ["--set", "control.end_time=%g" % end_time]
    try:
        # OpenMPI refuses to start as root (containers, CI) unless told it may
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        r = subprocess.run(args, capture_output=True, text=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return False, "still running after %d s" % timeout
    if r.returncode != 0:
        last = r.stderr.strip().splitlines()[-1:] or [""]
        return False, "exit %d: %s" % (r.returncode, last[0][:200])
    for name in ("history.csv", "energy.csv"):
        with open(os.path.join(folder, "results", name), "rb") as a, \
                open(os.path.join(out, name), "rb") as b:
            if a.read() != b.read():
                return False, "%s differs" % name
    return True, "the same bytes"


def published_values(deck, results):
    """For each published LS-DYNA value of the deck (manifest key `published`), fpmshell's from
    its run's results: (entry, fpmshell value or None)."""
    out = []
    for entry in deck.get("published", []):
        path = os.path.join(results, entry["file"])
        value = None
        if os.path.exists(path):
            with open(path) as f:
                rows = [line.rstrip("\n").split(",") for line in f if line.strip()]
            if rows and entry["column"] in rows[0]:
                k = rows[0].index(entry["column"])
                column = [float(r[k]) for r in rows[1:]]
                if column:
                    take = entry["take"]
                    # "largest magnitude": sign conventions of wall forces differ between codes
                    value = (column[-1] if take == "final" else max(column) if take == "max" else
                             min(column) if take == "min" else max(abs(v) for v in column))
        out.append((entry, value))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--fpmshell", default=os.path.join(ROOT, "build", "fpmshell"))
    ap.add_argument("--mirrors", default="/work/.mirror")
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "deck_corpus"))
    ap.add_argument("--output", default=os.path.join(ROOT, "docs", "deck-corpus.md"))
    ap.add_argument("--manifest", default=os.path.join(ROOT, "tools", "deck_corpus.json"))
    ap.add_argument("--end-time", type=float, default=None,
                    help="run each deck to this time instead of its own end time")
    ap.add_argument("--timeout", type=int, default=1800, help="seconds a run may take")
    ap.add_argument("--only", nargs="*", default=None)
    ap.add_argument("--ranks", type=int, default=0,
                    help="also run every deck that ran on this many ranks and compare")
    ap.add_argument("--mpiexec", default="mpirun")
    args = ap.parse_args()
    fpm = os.path.abspath(args.fpmshell)
    decks = json.load(open(args.manifest))["decks"]
    rows, wrong = [], 0
    for deck in decks:
        if args.only and deck["name"] not in args.only:
            continue
        try:
            path = lay_out(deck, args.mirrors, args.work)
            result, detail, elements, wall = run_deck(fpm, path, args.end_time, args.timeout)
        except RuntimeError as e:
            result, detail, elements, wall = "not laid out", str(e), None, 0.0
        expected = "ran" if deck["scope"] == "shells" else "refused"
        as_promised = result == expected
        on_ranks = ""
        if args.ranks > 1 and result == "ran":
            same, on_ranks = same_on_ranks(fpm, args.mpiexec, args.ranks, path, args.end_time,
                                           args.timeout)
            as_promised = as_promised and same
        wrong += 0 if as_promised else 1
        detail = detail.replace(os.path.abspath(args.work) + os.sep, "")
        results = os.path.join(os.path.dirname(path), "results") if result == "ran" else ""
        compared = published_values(deck, results) if result == "ran" and not args.end_time else []
        rows.append((deck, result, detail, elements, wall, as_promised, compared, on_ranks))
        print("%-14s %-8s %s%s%s" % (deck["name"], result, "" if as_promised else "(NOT AS PROMISED) ",
                                    detail[:200], " on %d ranks: %s" % (args.ranks, on_ranks)
                                    if on_ranks else ""))
    lines = [
        "# Public LS-DYNA decks",
        "",
        "Decks written by others, run as they are by `tools/deck_corpus.py` (the list:",
        "`tools/deck_corpus.json`; each laid out from a local mirror of its repository, none",
        "committed here). A deck of shells (and rigid solids) must run; any other must be refused with",
        "exit 2 and one sentence naming file, line and card. Run of %s with %s."
        % (datetime.date.today().isoformat(),
           subprocess.run([fpm, "--version"], capture_output=True, text=True).stdout.strip()),
        "",
        "| deck | source | what | elements | scope | result | wall s |%s as promised |"
        % (" on %d ranks |" % args.ranks if args.ranks > 1 else ""),
        "|---|---|---|---|---|---|---|%s---|" % ("---|" if args.ranks > 1 else ""),
    ]
    for deck, result, detail, elements, wall, ok, _, on_ranks in rows:
        source = "%s `%s` (%s)" % (deck["repo"], deck["files"][0], deck["licence"])
        text = result + (": " + detail.replace("|", "\\|") if detail else "")
        lines.append("| %s | %s | %s | %s | %s | %s | %s |%s %s |" % (
            deck["name"], source, deck["what"], elements if elements is not None else "",
            deck["scope"], text, "%.1f" % wall if result == "ran" else "",
            " %s |" % on_ranks if args.ranks > 1 else "", "yes" if ok else "**no**"))
    lines += ["", "%d of %d decks as promised." % (len(rows) - wrong, len(rows)), ""]
    table = [r for r in rows if r[6]]  # those with published values
    if table:
        lines += ["## Published LS-DYNA results beside fpmshell's", "",
                  "| deck | quantity | LS-DYNA | LS-DYNA's runs spread | fpmshell | difference | source |",
                  "|---|---|---|---|---|---|---|"]
        for deck, *_, compared, _ in table:
            for entry, value in compared:
                ref = entry["lsdyna"]
                diff = "%+.1f %%" % (100 * (value - ref) / abs(ref)) if value is not None and ref else ""
                spread = ("%.6g to %.6g" % tuple(entry["lsdyna_range"])
                          if "lsdyna_range" in entry else "")
                lines.append("| %s | %s | %.6g %s | %s | %s | %s | %s |" % (
                    deck["name"], entry["quantity"], ref, entry["unit"], spread,
                    "%.6g %s" % (value, entry["unit"]) if value is not None else "not in the results",
                    diff, deck.get("published_source", "")))
        lines.append("")
    for note in json.load(open(args.manifest)).get("notes", []):
        lines += [note, ""]
    with open(args.output, "w") as f:
        f.write("\n".join(lines))
    print("wrote %s: %d of %d as promised" % (args.output, len(rows) - wrong, len(rows)))
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())

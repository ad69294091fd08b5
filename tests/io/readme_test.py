#!/usr/bin/env python3
"""The README is true (test io.readme): every command it shows runs, and prints what it says.

    readme_test.py FPMSHELL WORK_DIR

- Every ```sh block of README.md is run, line by line, from the repository's root: `build/fpmshell`
  is the fpmshell under test, `python3` this interpreter, and `results/` a folder under WORK_DIR
  (the test writes nothing into the repository). A command that exits other than 0 fails.
- The ```text block that follows a ```sh block lists what those commands print: each of its lines
  must be a whole line of their output, `…` standing for any text.
- A ```yaml block is a file's content: the last `path.yaml` the text before it names, whose
  lines (comment lines aside) must hold the block as it is.
- Every relative link of the README names a file or folder of the repository, and every image it
  shows exists (`make picture` draws them).
`make run` runs on the build under test (its results under WORK_DIR); `make test` itself is not
run (it is what runs this).
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def blocks(text):
    """(language, lines, text before the block) of every fenced block, in order."""
    out, prose = [], []
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        m = re.match(r"^```(\w*)\s*$", lines[i])
        if not m:
            prose.append(lines[i])
            i += 1
            continue
        j = i + 1
        while j < len(lines) and lines[j].strip() != "```":
            j += 1
        out.append((m.group(1), lines[i + 1:j], "\n".join(prose)))
        prose = []
        i = j + 1
    return out


def pattern(line):
    return re.compile("".join(".*" if part == "…" else re.escape(part)
                              for part in re.split("(…)", line.strip())))


def main():
    fpmshell, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    os.makedirs(work, exist_ok=True)
    results = os.path.join(work, "results")
    with open(os.path.join(ROOT, "README.md")) as f:
        text = f.read()
    failures, commands = [], 0
    found = blocks(text)
    output = None  # what the last ```sh block printed
    for language, lines, before in found:
        if language == "sh":
            output = []
            for line in (l.strip() for l in lines):
                if not line or line.startswith("#"):
                    continue
                words = line.split()
                if words[:2] == ["make", "test"]:
                    continue  # what runs this test
                if words[:2] == ["make", "run"]:  # on the build under test, results in WORK_DIR
                    words += ["BUILD=" + os.path.dirname(fpmshell), "PYTHON=" + sys.executable,
                              "RESULTS=" + os.path.join(results, "spherical_cap_elastic")]
                elif words[0] == "build/fpmshell":
                    words[0] = fpmshell
                elif words[0] == "python3":
                    words[0] = sys.executable
                words = [w.replace("results/", results + "/", 1) if w.startswith("results/") else w
                         for w in words]
                commands += 1
                p = subprocess.run(words, cwd=ROOT, capture_output=True, text=True, timeout=600)
                output += (p.stdout + p.stderr).replace(results + "/", "results/").splitlines()
                if p.returncode != 0:
                    failures.append("`%s` exited %d: %s" % (line, p.returncode, p.stderr[-300:]))
        elif language == "text":
            if output is None:
                failures.append("a text block before any command: %r" % lines[:1])
                continue
            for line in (l for l in lines if l.strip()):
                if not any(pattern(line).fullmatch(o.strip()) for o in output):
                    failures.append("the README says the commands print %r; they did not" % line)
            output = None
        elif language == "yaml":
            named = re.findall(r"`([\w./-]+\.yaml)`", before)
            if not named:
                failures.append("a yaml block that names no file before it")
                continue
            with open(os.path.join(ROOT, named[-1])) as f:
                content = [l for l in f.read().split("\n") if not l.lstrip().startswith("#")]
            n = len(lines)
            if not any(content[k:k + n] == lines for k in range(len(content) - n + 1)):
                failures.append("the yaml block is not the content of %s" % named[-1])
    for target in re.findall(r"\]\(([^)#:]+)(?:#[^)]*)?\)", text):
        if not os.path.exists(os.path.join(ROOT, target)):
            failures.append("the link %s names nothing in the repository" % target)
    if commands < 5:
        failures.append("only %d commands found in the README's sh blocks" % commands)
    if len(text.split("\n")) > 200:
        failures.append("the README has %d lines (at most 200)" % len(text.split("\n")))
    for f in failures:
        print("FAIL:", f)
    print("%d commands of README.md run, %d failures" % (commands, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Writes the seed corpus of every fuzz target (fuzz/README.md) into OUT/<target>/:

  model_yaml     every model file of examples/, validation/, bench/ and fuzz/models/, with its
                 generated mesh made coarse (a few dozen triangles)
  set_overrides  fuzz/seeds/set_overrides/ (one override per line)
  gmsh_msh       the .msh files of the repository and the Gmsh meshes written in the unit tests
  abaqus_inp     the .inp files of the repository and those written in the unit tests
  lsdyna_k       the .k files of the repository and those written in the unit tests
  restart_file   restart files of fuzz/models/plate_on_anvil.yaml, without their checksum (the
                 target appends it): one as the plate touches the anvil, one during the impact

usage: seed_corpora.py --fpmshell BIN --out OUT
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TARGETS = ["model_yaml", "set_overrides", "gmsh_msh", "abaqus_inp", "lsdyna_k", "restart_file"]
MESH_DIVISIONS = 4  # the seeds' generated meshes: a few dozen triangles (coarse())
CHECKSUM_BYTES = 4  # the CRC-32 at the end of a restart file (io/restart_archive.cpp)


def repository_files(*patterns):
    files = []
    for pattern in patterns:
        files += glob.glob(os.path.join(ROOT, pattern), recursive=True)
    return sorted(f for f in files if "/build" not in f)


def test_literals(start):
    """The raw string literals R"(...)" of the unit tests whose text starts with `start`."""
    found = []
    for path in repository_files("tests/unit/**/*.cpp"):
        for text in re.findall(r'R"\((.*?)\)"', open(path).read(), re.S):
            if text.lstrip().upper().startswith(start.upper()):
                found.append(text)
    return found


def coarse(model):
    """The model with at most MESH_DIVISIONS divisions in each direction of a generated mesh: the
    fuzzer explores the keys, not the mesh size, and a seed of 10^5 elements would make every
    input it derives take a second."""
    return re.sub(r"\b(nx|ny|n|divisions\w*)(\s*:\s*)(\d+)\b(?!\.)",
                  lambda m: m.group(1) + m.group(2) + str(min(int(m.group(3)), MESH_DIVISIONS)), model)


def restart_seeds(fpmshell, work):
    model = os.path.join(ROOT, "fuzz", "models", "plate_on_anvil.yaml")
    seeds = []
    for name, end_time in (("early", "1.2e-5"), ("impact", "4.0e-5")):
        out = os.path.join(work, name)
        run = subprocess.run([fpmshell, "run", model, "-o", out, "--quiet", "--threads", "1",
                              "--restart-every", "1e9", "--set", "control.end_time=" + end_time],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if run.returncode != 0:
            sys.exit("seed_corpora: the run of %s failed (exit %d): %s" % (model, run.returncode, run.stdout))
        seeds.append((name, open(os.path.join(out, "restart.bin"), "rb").read()[:-CHECKSUM_BYTES]))
    return seeds


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--fpmshell", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    for t in TARGETS:
        shutil.rmtree(os.path.join(args.out, t), ignore_errors=True)
        os.makedirs(os.path.join(args.out, t))

    def put(target, name, content):
        mode = "wb" if isinstance(content, bytes) else "w"
        with open(os.path.join(args.out, target, name), mode) as f:
            f.write(content)

    for f in repository_files("examples/**/*.yaml", "validation/**/*.yaml", "bench/**/*.yaml",
                              "fuzz/models/*.yaml"):
        put("model_yaml", os.path.relpath(f, ROOT).replace("/", "_"), coarse(open(f).read()))
    for f in repository_files("fuzz/seeds/set_overrides/*"):
        put("set_overrides", os.path.basename(f), open(f).read())
    for target, ext, start in (("gmsh_msh", "msh", "$MeshFormat"), ("abaqus_inp", "inp", "*"),
                               ("lsdyna_k", "k", "*KEYWORD")):
        for f in repository_files("**/*." + ext):
            put(target, os.path.relpath(f, ROOT).replace("/", "_"), open(f, "rb").read())
        literals = test_literals(start)
        if ext == "inp":  # the Abaqus files of the tests: those that are not LS-DYNA decks
            literals = [t for t in literals if not t.lstrip().upper().startswith("*KEYWORD")]
        for i, text in enumerate(literals):
            put(target, "unit_test_%d.%s" % (i, ext), text)
    with tempfile.TemporaryDirectory() as work:
        for name, content in restart_seeds(args.fpmshell, work):
            put("restart_file", name, content)
    for t in TARGETS:
        n = len(os.listdir(os.path.join(args.out, t)))
        if n == 0:
            sys.exit("seed_corpora: no seed for %s" % t)
        print("%-14s %3d seeds" % (t, n))


if __name__ == "__main__":
    main()

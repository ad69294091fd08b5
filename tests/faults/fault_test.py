"""Fault tests (docs/reliability.md): what fpmshell does when the world around it fails.

- a full disk (full_disk_preload.cpp) at several points of a run: exit 1 with one sentence
  naming the file and "No space left on device", no temporary file left, and every result file
  on disk readable (complete CSV rows, well-formed VTU and PVD, JSON);
- an output folder that cannot be written (a path through a file; a read-only folder, as an
  unprivileged user): a clear error, and the earlier results in it unchanged, byte for byte;
- a kill (SIGKILL) at random moments of a run that writes a frame, a history row and a restart
  file at every step: every file stays readable and the run resumes from its restart file;
- a damaged restart file (cut short at several lengths, a flipped bit, a byte more): refused with
  exit 2 and one sentence naming restart.bin;
- absurd declared sizes in mesh files (a .msh declaring 10^15 nodes, GENERATE ranges of 10^15
  ids in .inp and .k files, a damaged .msh that makes Gmsh allocate gigabytes): refused with
  exit 2, quickly and without allocating for them;
- NaN and Inf in the numbers of a model, of a mesh file and of an override: exit 2 naming the
  file, the line and the key.

usage: fault_test.py FPMSHELL FULL_DISK_PRELOAD WORKDIR
"""
import glob
import json
import os
import pwd
import random
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

FPM, PRELOAD, WORK = [os.path.abspath(a) for a in sys.argv[1:4]]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import fpmv  # noqa: E402  (the frames' reader of the validation scripts)
failures = []
passed = 0

PLATE = """title: fault test plate
mesh: {generator: plate, length_x: 1.0, length_y: 1.0, nx: 6, ny: 6}
materials:
  s: {type: elastic, density: 7800, youngs_modulus: 2.1e11, poisson_ratio: 0.3}
sections:
  - {elements: all, material: s, thickness: 0.01}
boundary:
  - {nodes: boundary, fix: all}
loads:
  - {type: pressure, elements: all, value: 100}
control: {end_time: 2.0e-3}
output:
  every: 1.0e-5
  fields_every: 1.0e-4
  histories:
    - {name: w, nodes: all, quantity: uz, reduce: min}
"""


def check(name, cond, detail=""):
    global passed
    if cond:
        passed += 1
        print("ok   " + name)
    else:
        failures.append(name)
        print("FAIL " + name + ("\n     " + detail[:2000] if detail else ""))


def write(name, text):
    path = os.path.join(WORK, name)
    with open(path, "wb" if isinstance(text, bytes) else "w") as f:
        f.write(text)
    return path


def fpm(*args, env=None, preexec=None, timeout=300, program=None, cwd=None):
    full_env = dict(os.environ, OMP_NUM_THREADS="1")
    full_env.update(env or {})
    p = subprocess.run([program or FPM] + list(args), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, env=full_env, preexec_fn=preexec, timeout=timeout, cwd=cwd)
    return p.returncode, p.stdout


def error_lines(out):
    return [line for line in out.splitlines() if line.startswith("error")]


def unreadable_results(folder):
    """The result files of `folder` that are not complete and readable (empty: all are)."""
    bad = []
    for csv in ("history.csv", "energy.csv"):
        path = os.path.join(folder, csv)
        if not os.path.exists(path):
            continue
        rows = open(path).read().splitlines()
        width = len(rows[0].split(",")) if rows else 0
        try:
            ok = width > 1 and all(len(r.split(",")) == width for r in rows[1:])
            for r in rows[1:]:
                [float(x) for x in r.split(",")]  # every field a number
        except ValueError:
            ok = False
        if not ok:
            bad.append(csv)
    for pvd in glob.glob(os.path.join(folder, "*.pvd")):
        try:
            ET.parse(pvd)
        except ET.ParseError as e:
            bad.append("%s (%s)" % (os.path.relpath(pvd, folder), e))
    for vtu in glob.glob(os.path.join(folder, "fields", "*.vtu")):
        problem = frame_problem(vtu)
        if problem:
            bad.append("%s (%s)" % (os.path.relpath(vtu, folder), problem))
    summary = os.path.join(folder, "summary.json")
    if os.path.exists(summary):
        try:
            json.load(open(summary))
        except ValueError:
            bad.append("summary.json")
    bad += [os.path.relpath(t, folder) for t in glob.glob(os.path.join(folder, "**", "*.tmp.*"), recursive=True)]
    return bad


def frame_problem(path):
    """Why the frame at `path` is not whole ("" when it is): its XML part must parse (the raw
    appended bytes follow it), and every array must hold as many values as the piece declares."""
    data = open(path, "rb").read()
    head = data.split(b"<AppendedData", 1)[0]
    if b"<AppendedData" in data:
        head += b"</VTKFile>"
    try:
        piece = ET.fromstring(head).find("UnstructuredGrid/Piece")
        points, cells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))
        arrays = fpmv.read_vtu(path)
    except Exception as e:  # any failure to read is the finding
        return "%s: %s" % (type(e).__name__, e)
    expected = {"points": points, "connectivity": 3 * cells, "offsets": cells, "types": cells}
    for name, values in arrays.items():
        if len(values) != expected.get(name, points if name in POINT_ARRAYS else cells):
            return "array %s holds %d values" % (name, len(values))
    return ""


POINT_ARRAYS = ("displacement", "velocity", "rotation")


def snapshot(folder):
    """{file: bytes} of every file under folder."""
    out = {}
    for root, _, files in os.walk(folder):
        for f in files:
            p = os.path.join(root, f)
            out[os.path.relpath(p, folder)] = open(p, "rb").read()
    return out


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
plate = write("plate.yaml", PLATE)

# ---- a full disk ----------------------------------------------------------------------------
# The disk fills after `budget` bytes: before the first file, during the first frame, and at
# several points of the run (a run writes about 600 kB: 21 frames, the CSV files re-written).
disk_env = {"LD_PRELOAD": PRELOAD, "ASAN_OPTIONS": os.environ.get("ASAN_OPTIONS", "") + ":verify_asan_link_order=0"}
for budget in (0, 2000, 20000, 150000, 400000):
    res = os.path.join(WORK, "full_%d" % budget)
    os.makedirs(res)
    env = dict(disk_env, FPMSHELL_FULL_DISK_DIR=res, FPMSHELL_FULL_DISK_BYTES=str(budget))
    code, out = fpm("run", plate, "-o", res, "--quiet", env=env)
    errors = error_lines(out)
    # no byte at all: the output folder cannot be prepared, refused before the run (exit 2)
    check("full disk after %d bytes: exit %d, one sentence naming the file and the reason" % (budget, 2 if budget == 0 else 1),
          code == (2 if budget == 0 else 1) and len(errors) == 1 and "No space left on device" in errors[0] and res in errors[0],
          "exit %d: %s" % (code, out))
    bad = unreadable_results(res)
    check("full disk after %d bytes: every result file left readable, no temporary file" % budget,
          not bad, str(bad))

# ---- an output folder that cannot be written --------------------------------------------------
code, out = fpm("run", plate, "-o", os.path.join(plate, "results"), "--quiet")
errors = error_lines(out)
check("an output folder inside a file: exit 2, one sentence naming it",
      code == 2 and len(errors) == 1 and "plate.yaml/results" in errors[0], out)

def folder_others_can_reach():
    """A new folder that any user can traverse, for the unprivileged user's run: WORK lies in
    the clone, whose parent may be a private folder (a home of mode 0700) that only its owner
    can pass through. The first of $TMPDIR, /tmp, /var/tmp, /dev/shm whose every ancestor
    others may traverse; None if there is none."""
    for base in (tempfile.gettempdir(), "/tmp", "/var/tmp", "/dev/shm"):
        base = os.path.realpath(base)
        ancestors, p = [], base
        while True:
            ancestors.append(p)
            if p == os.path.dirname(p):
                break
            p = os.path.dirname(p)
        if os.path.isdir(base) and all(os.stat(a).st_mode & 0o001 for a in ancestors):
            folder = tempfile.mkdtemp(prefix="fpmshell-faults-", dir=base)
            os.chmod(folder, 0o755)
            return folder
    return None


# Root writes anywhere: the second run into the read-only folder is then an unprivileged
# user's, with a copy of the program and of the model in a folder that user can reach (the same
# program, model and results; only their place differs).
demote, ro_program, ro_model, ro_base = None, FPM, plate, WORK
if os.geteuid() == 0:
    ro_base = folder_others_can_reach()
    if ro_base is not None:
        nobody = pwd.getpwnam("nobody")
        ro_program = shutil.copy2(FPM, os.path.join(ro_base, "fpmshell"))
        ro_model = shutil.copy2(plate, os.path.join(ro_base, "plate.yaml"))
        os.chmod(ro_program, 0o755)
        os.chmod(ro_model, 0o644)
        demote = lambda: (os.setgroups([]), os.setgid(nobody.pw_gid), os.setuid(nobody.pw_uid))
check("a folder for the unprivileged user's run (every ancestor traversable by others)",
      ro_base is not None, "none of $TMPDIR, /tmp, /var/tmp, /dev/shm is reachable by every user")
if ro_base is not None:
    ro = os.path.join(ro_base, "read_only")
    code, out = fpm("run", ro_model, "-o", ro, "--quiet")
    check("a first run writes the results later made read-only", code == 0, out)
    before = snapshot(ro)
    for root, dirs, files in os.walk(ro):
        os.chmod(root, 0o555)
    code, out = fpm("run", ro_model, "-o", ro, "--quiet", "--overwrite", preexec=demote,
                    program=ro_program, cwd=ro_base)
    errors = error_lines(out)
    check("a read-only result folder: exit 2, one sentence naming it", code == 2 and len(errors) == 1
          and ro in errors[0], "exit %d: %s" % (code, out))
    check("a read-only result folder: the earlier results unchanged", snapshot(ro) == before)
    for root, dirs, files in os.walk(ro):
        os.chmod(root, 0o755)
    if ro_base != WORK:
        shutil.rmtree(ro_base)

# ---- a kill during a write --------------------------------------------------------------------
# A frame, a history row and a restart file at every step of a larger plate (writing is most of
# the run): each kill lands in or between writes; the files must stay readable and resumable.
busy = write("busy.yaml", PLATE.replace("nx: 6, ny: 6", "nx: 24, ny: 24")
             .replace("every: 1.0e-5\n  fields_every: 1.0e-4", "every: 0\n  fields_every: 1.0e-9"))
rng = random.Random(20261202)
kills = 0
for trial in range(8):
    res = os.path.join(WORK, "killed_%d" % trial)
    p = subprocess.Popen([FPM, "run", busy, "-o", res, "--quiet", "--restart-every", "1e-9"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                         env=dict(os.environ, OMP_NUM_THREADS="1"))
    # wait for the first restart file, then kill at a random moment of the next writes
    deadline = time.time() + 60
    while not os.path.exists(os.path.join(res, "restart.bin")) and time.time() < deadline and p.poll() is None:
        time.sleep(0.005)
    time.sleep(rng.uniform(0.0, 0.3))
    if p.poll() is None:
        p.send_signal(signal.SIGKILL)
        kills += 1
    p.wait()
    bad = unreadable_results(res)
    bad = [b for b in bad if ".tmp." not in b]  # a killed writer leaves its temporary file
    check("kill %d: every result file readable" % trial, not bad, str(bad))
    code, out = fpm("run", busy, "-o", res, "--quiet", "--resume", "--set", "control.end_time=2.2e-3")
    check("kill %d: the run resumes from its restart file and ends" % trial, code == 0, out)
    check("kill %d: the resumed run leaves no temporary file" % trial, not unreadable_results(res),
          str(unreadable_results(res)))
check("the kills landed during the runs", kills >= 6, "%d of 8" % kills)

# ---- a damaged restart file -------------------------------------------------------------------
res = os.path.join(WORK, "restart")
code, out = fpm("run", plate, "-o", res, "--quiet", "--restart-every", "1e9",
                "--set", "control.end_time=1e-3")
good = open(os.path.join(res, "restart.bin"), "rb").read()
damaged = {"empty": b"", "the magic word only": good[:8], "cut after the header": good[:20],
           "cut in half": good[:len(good) // 2], "one byte short": good[:-1],
           "a flipped bit": good[:len(good) // 3] + bytes([good[len(good) // 3] ^ 4]) + good[len(good) // 3 + 1:],
           "a changed checksum": good[:-1] + bytes([good[-1] ^ 1]), "a byte more": good + b"\0"}
for name, content in damaged.items():
    open(os.path.join(res, "restart.bin"), "wb").write(content)
    code, out = fpm("run", plate, "-o", res, "--resume", "--quiet")
    errors = error_lines(out)
    check("a restart file with %s: exit 2, one sentence naming it" % name,
          code == 2 and len(errors) == 1 and "restart.bin" in errors[0], "exit %d: %s" % (code, out))

# ---- absurd declared sizes --------------------------------------------------------------------
def peak_memory_run(*args):
    """Runs fpmshell, returns (exit code, output, peak resident memory in MB of the run)."""
    probe = ("import resource, subprocess, sys\n"
             "p = subprocess.run(sys.argv[1:], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)\n"
             "print(p.stdout, end='')\n"
             "print('PEAK_KB', resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
             "sys.exit(p.returncode)\n")
    p = subprocess.run([sys.executable, "-c", probe, FPM] + list(args), stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=120)
    lines = p.stdout.splitlines()
    peak = int(lines[-1].split()[1]) / 1024 if lines and lines[-1].startswith("PEAK_KB") else -1
    return p.returncode, "\n".join(lines[:-1]), peak


def mesh_model(mesh_file):
    return write(mesh_file + ".yaml", PLATE.replace("mesh: {generator: plate, length_x: 1.0, length_y: 1.0, nx: 6, ny: 6}",
                                                    "mesh: {file: %s}" % mesh_file).replace("{nodes: boundary, fix: all}", "{nodes: all, fix: all}"))


absurd = {
    "huge.msh": "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000000000000000 1 1000000000000000\n"
                "2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n",
    "huge2.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1000000000000000\n1 0 0 0\n$EndNodes\n",
    # Found by the gmsh_msh fuzz target: 144 bytes that made Gmsh take 7.6 GB and 11 s before it
    # failed, stopped now by the memory limit of Gmsh's child process (gmsh_reader.cpp)
    "damaged.msh": b"$MeshFormat\x084or s\n3 7 11 \xfd$Mes\xedhFormat\n5.es\n7\n1 0 \n4 0.5 0 0\n5 0.5 0.5 0\n"
                   b"6 0 0.5 0[\n1\n$2 \x009\x00$N$.2 0 8\n$End\n\n$Es\n$Elements\n1\ndes\n$Elements\n1\n$ 21",
    "huge.inp": "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n*ELEMENT, TYPE=S3\n1, 1, 2, 3\n"
                "*NSET, NSET=ALLN, GENERATE\n1, 1000000000000000, 1\n",
    "huge.k": "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n*ELEMENT_SHELL\n1,1,1,2,3,3\n"
              "*SET_NODE_LIST_GENERATE\n1\n1,1000000000000000\n*END\n",
}
for name, text in absurd.items():
    write(name, text)
    code, out, peak = peak_memory_run("check", mesh_model(name))
    errors = error_lines(out)
    check("%s with an absurd declared size: exit 2, one sentence naming it, under 500 MB (%.0f MB)" % (name, peak),
          code == 2 and len(errors) == 1 and name in errors[0] and 0 < peak < 500, "exit %d: %s" % (code, out))

# ---- NaN and Inf in numbers -------------------------------------------------------------------
not_finite = {
    "nan_thickness": (PLATE.replace("thickness: 0.01", "thickness: .nan"), "thickness"),
    "inf_end_time": (PLATE.replace("end_time: 2.0e-3", "end_time: .inf"), "end_time"),
    "nan_pressure": (PLATE.replace("value: 100", "value: .NaN"), "value"),
    "inf_modulus": (PLATE.replace("youngs_modulus: 2.1e11", "youngs_modulus: -.inf"), "youngs_modulus"),
    "nan_velocity": (PLATE + "initial_conditions:\n  - {nodes: all, velocity: [.nan, 0, 0]}\n", "velocity"),
}
for name, (text, key) in not_finite.items():
    code, out = fpm("check", write(name + ".yaml", text))
    errors = error_lines(out)
    check("%s: exit 2 naming the file, line and key" % name,
          code == 2 and len(errors) == 1 and (name + ".yaml:") in errors[0] and key in errors[0], out)
code, out = fpm("check", plate, "--set", "control.end_time=.inf")
check("an override to Inf: exit 2 naming --set and the key", code == 2 and "--set" in out and "end_time" in out, out)
meshes = {
    "nan.inp": "*NODE\n1, 0, 0, 0\n2, nan, 0, 0\n3, 0, 1, 0\n*ELEMENT, TYPE=S3\n1, 1, 2, 3\n",
    "inf.k": "*KEYWORD\n*NODE\n1,0,0,0\n2,1,inf,0\n3,0,1,0\n*ELEMENT_SHELL\n1,1,1,2,3,3\n*END\n",
    "nan.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n$EndNodes\n"
               "$Elements\n1\n1 2 0 1 2 3\n$EndElements\n",
}
for name, text in meshes.items():
    write(name, text)
    code, out = fpm("check", mesh_model(name))
    errors = error_lines(out)
    check("%s: exit 2 naming the mesh file" % name, code == 2 and len(errors) == 1 and name in errors[0], out)

print("\n%d passed, %d failed" % (passed, len(failures)))
sys.exit(1 if failures else 0)

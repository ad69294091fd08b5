"""The VTU frames of a run, loaded by VTK's own reader (python3-vtk9, vtkXMLUnstructuredGridReader),
an implementation independent of fpmshell's writer: for every output.fields_encoding (raw
appended, the default; base64; ascii) and for raw with zlib compression, every frame loads, has
the model's points and triangles, the standard arrays with their components, the time of the
.pvd in its TimeValue, and the same values in every encoding (bit for bit: the binary forms hold
the doubles themselves, the ascii form their shortest round-trip decimal). A frame of a plastic
run is checked against the run's own history (the minimum deflection) to show that the arrays
hold what the solver computed, not only what the writer was given.

usage: vtu_reader_test.py FPMSHELL WORKDIR
"""
import os
import re
import shutil
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

FPM, WORK = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_tally import check, finish  # noqa: E402

MODEL = """title: clamped plate under a pressure pulse, yielding
mesh: {generator: plate, length_x: 0.2, length_y: 0.1, nx: 6, ny: 3}
materials:
  steel: {type: j2_plastic, density: 7800, youngs_modulus: 2.1e11, poisson_ratio: 0.3,
          yield_stress: 2.0e8, tangent_modulus: 1.0e9}
sections:
  - {elements: all, material: steel, thickness: 0.002}
boundary:
  - {nodes: boundary, fix: all}
loads:
  - {type: pressure, elements: all, value: 2.0e6}
control: {end_time: 2.0e-4}
output:
  every: 2.0e-5
  fields_every: 5.0e-5
  histories:
    - {name: w_min, nodes: all, quantity: uz, reduce: min}
"""
ARRAYS = {  # name: components (output_fields.cpp standard_fields)
    "point": {"displacement": 3, "velocity": 3, "rotation": 3},
    "cell": {"membrane_force": 3, "bending_moment": 3, "thickness": 1,
             "plastic_strain_top": 1, "plastic_strain_middle": 1, "plastic_strain_bottom": 1},
}
FORMATS = {  # name: keys added to the output block (none: the default)
    "raw": [],
    "raw_zlib": ["fields_compression: zlib"],
    "base64": ["fields_encoding: base64"],
    "ascii": ["fields_encoding: ascii"],
}




def run(name, output_keys):
    model = os.path.join(WORK, name + ".yaml")
    with open(model, "w") as f:
        f.write(MODEL.replace("output:\n", "output:\n" + "".join(f"  {k}\n" for k in output_keys)))
    out = os.path.join(WORK, name)
    cmd = [FPM, "run", model, "-o", out, "--overwrite", "--quiet"]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    check(f"{name}: the run ends with exit 0", r.returncode == 0, r.stderr.strip())
    return out


def load(path):
    """The frame at `path` through VTK: (points, cells, {array: values}, time), or None."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode() != 0:
        return None
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()) if grid.GetPoints() else np.zeros((0, 3))
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    arrays = {}
    for kind, data in (("point", grid.GetPointData()), ("cell", grid.GetCellData())):
        for i in range(data.GetNumberOfArrays()):
            a = data.GetArray(i)
            arrays[(kind, a.GetName())] = (a.GetNumberOfComponents(), vtk_to_numpy(a).copy())
    time = grid.GetFieldData().GetArray("TimeValue")
    return points.copy(), cells.copy(), arrays, (time.GetValue(0) if time else None)


def pvd_frames(out):
    if not os.path.exists(os.path.join(out, "fields.pvd")):
        return []
    text = open(os.path.join(out, "fields.pvd")).read()
    return [(float(t), f) for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]


def main():
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)

    loaded = {}
    for name, output_keys in FORMATS.items():
        out = run(name, output_keys)
        frames = pvd_frames(out)
        check(f"{name}: the .pvd lists the frames", len(frames) >= 4, str(frames))
        loaded[name] = []
        for time, file in frames:
            frame = load(os.path.join(out, file))
            check(f"{name}: VTK reads {file}", frame is not None, "reader error")
            if frame is None:
                continue
            points, cells, arrays, frame_time = frame
            check(f"{name}: {file} has 28 points and 36 triangles",
                  points.shape == (28, 3) and cells.size == 108, f"{points.shape} {cells.size}")
            check(f"{name}: {file} holds its time", frame_time == time, f"{frame_time} vs {time}")
            for kind, names in ARRAYS.items():
                for array, components in names.items():
                    got = arrays.get((kind, array))
                    check(f"{name}: {file} has the {kind} array {array} x {components}",
                          got is not None and got[0] == components, str(got and got[0]))
            loaded[name].append(frame)
        first = os.path.join(out, "fields", "frame_00000.vtu")
        head = open(first, "rb").read(2048) if os.path.exists(first) else b""
        layout = {"raw": b'format="appended"', "raw_zlib": b'compressor="vtkZLibDataCompressor"',
                  "base64": b'format="binary"', "ascii": b'format="ascii"'}[name]
        check(f"{name}: the file is written in that encoding", layout in head, head[:400])

    reference = loaded["raw"]
    for name in ("raw_zlib", "base64", "ascii"):
        same = len(loaded[name]) == len(reference) and all(
            np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1]) and a[2].keys() == b[2].keys()
            and all(np.array_equal(a[2][k][1], b[2][k][1]) for k in a[2])
            for a, b in zip(loaded[name], reference))
        check(f"{name}: every frame holds the values of the raw frames bit for bit", same)

    # the last frame against the run's own history: the lowest z displacement, and yielding
    last = reference[-1]
    if not reference:
        print("FAIL no raw frames")
        return 1
    rows = [line.split(",") for line in open(os.path.join(WORK, "raw", "history.csv"))][1:]
    w_min = float(rows[-1][1])
    uz = last[2][("point", "displacement")][1][:, 2]
    # 1e-9: history.csv holds 10 significant digits
    check("the last frame's displacements are the history's (w_min)",
          abs(uz.min() - w_min) <= 1e-9 * abs(w_min), f"{uz.min()} vs {w_min}")
    check("the pulse yields the plate (plastic strain in the last frame)",
          last[2][("cell", "plastic_strain_top")][1].max() > 0)

    return finish()


if __name__ == "__main__":
    sys.exit(main())

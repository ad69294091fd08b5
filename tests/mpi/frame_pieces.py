"""A frame of a distributed run (fields/frame_NNNNN.pvtu and its pieces, one .vtu per rank)
loaded by VTK's own reader (vtkXMLPUnstructuredGridReader) and joined by its `particle_index`
and `element_index` arrays into the order of a single-process frame; then compared with that
frame (fields/frame_NNNNN.vtu, vtkXMLUnstructuredGridReader) value by value, bit for bit.
"""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader


def load(path):
    reader = vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def triangles(grid):
    """The cells' corners, one row per cell (every cell a triangle)."""
    return vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 3)


def arrays(data):
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}


def differences(single_vtu, pieces_pvtu):
    """What differs between the single-process frame and the joined pieces (empty: none)."""
    one, joined = load(single_vtu), load(pieces_pvtu)
    out = []
    point_data, cell_data = arrays(joined.GetPointData()), arrays(joined.GetCellData())
    if "particle_index" not in point_data or "element_index" not in cell_data:
        return ["%s has no particle_index or element_index array" % pieces_pvtu]
    pid = point_data.pop("particle_index").astype(np.int64)
    eid = cell_data.pop("element_index").astype(np.int64)
    if not np.array_equal(np.sort(eid), np.arange(one.GetNumberOfCells())):
        out.append("the pieces do not hold every cell once (%d cells for %d)"
                   % (len(eid), one.GetNumberOfCells()))
        return out
    if not np.array_equal(np.unique(pid), np.arange(one.GetNumberOfPoints())):
        out.append("the pieces do not hold every point")
        return out
    # a point held by several pieces has the same bits in each: compare every copy
    if not np.array_equal(vtk_to_numpy(one.GetPoints().GetData())[pid],
                          vtk_to_numpy(joined.GetPoints().GetData())):
        out.append("points differ")
    if not np.array_equal(triangles(one)[eid], pid[triangles(joined)]):
        out.append("triangles differ")
    for where, mine, theirs in (("point", point_data, arrays(one.GetPointData())),
                                ("cell", cell_data, arrays(one.GetCellData()))):
        if sorted(mine) != sorted(theirs):
            out.append("%s arrays %s against %s" % (where, sorted(mine), sorted(theirs)))
            continue
        order = pid if where == "point" else eid
        for name, values in mine.items():
            if not np.array_equal(theirs[name][order], values):
                out.append("%s array %s differs" % (where, name))
    return out

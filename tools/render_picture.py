#!/usr/bin/env python3
"""The README's picture and plot (`make picture`): the last frame of a run rendered in 3D with
matplotlib (the cells coloured by their largest plastic strain through the thickness, shaded by
their normal), and two columns of its history.csv plotted against each other.

    python3 tools/render_picture.py RESULTS_DIR PICTURE.png [--mirror xy] [--title TEXT]
        [--plot PLOT.png --x COLUMN --y COLUMN --x-scale S --y-scale S --x-label L --y-label L]

--mirror xy: the frame is a quarter model with the symmetry planes x = 0 and y = 0 (the square
tube): it is reflected into the whole tube, whose far walls are left out. VTK reads the frame (.vtu or .pvtu, the last
one fields.pvd lists); matplotlib draws it, so no display or OpenGL is needed.
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fpmv  # noqa: E402

k_elevation, k_azimuth = np.radians(22.0), np.radians(-55.0)  # the camera


def last_frame(results):
    """Points (n x 3), triangles (m x 3) and the largest plastic strain of each cell of the last
    frame fields.pvd lists."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    datasets = ET.parse(os.path.join(results, "fields.pvd")).getroot().iter("DataSet")
    name = [d.get("file") for d in datasets][-1]
    path = os.path.join(results, name)
    reader = (vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu")
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    cells = vtk_to_numpy(grid.GetCells().GetData()).reshape(-1, 4)[:, 1:]
    data = grid.GetCellData()
    strains = [vtk_to_numpy(data.GetArray(n)) for n in
               ("plastic_strain_top", "plastic_strain_middle", "plastic_strain_bottom")
               if data.GetArray(n) is not None]
    strain = np.max(strains, axis=0) if strains else np.zeros(len(cells))
    return points, cells, strain


def mirrored(points, cells, strain):
    """The quarter model reflected in x = 0 and y = 0: four copies."""
    all_points, all_cells, all_strain = [], [], []
    for sx, sy in ((1, 1), (-1, 1), (1, -1), (-1, -1)):
        p = points * np.array([sx, sy, 1.0])
        c = cells if sx * sy > 0 else cells[:, ::-1]  # one reflection turns the normals
        all_cells.append(c + len(points) * len(all_points))
        all_points.append(p)
        all_strain.append(strain)
    return np.vstack(all_points), np.vstack(all_cells), np.concatenate(all_strain)


def render(points, cells, strain, out, title, cull=False):
    plt = fpmv.pyplot()
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    triangles = points[cells]
    normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-30)
    if cull:
        # the straight walls of a tube about the z axis, seen from outside: a face whose normal
        # is nearly horizontal and turned (outward) away from the eye is hidden by the near
        # walls; leaving it out spares matplotlib's depth sort (by face, not by pixel) the
        # faces it would misplace
        elev, azim = k_elevation, k_azimuth
        eye = np.array([np.cos(elev) * np.cos(azim), np.cos(elev) * np.sin(azim), np.sin(elev)])
        centre_xy = points[:, :2].mean(axis=0)
        away = triangles.mean(axis=1)[:, :2] - centre_xy
        outward = np.sign(np.einsum("ij,ij->i", normals[:, :2], away))
        flat = np.linalg.norm(normals[:, :2], axis=1) > 0.95
        keep = ~(flat & ((normals * outward[:, None]) @ eye < 0))
        triangles, normals, strain = triangles[keep], normals[keep], strain[keep]
    light = np.array([0.4, -0.7, 0.6])
    light /= np.linalg.norm(light)
    shade = 0.35 + 0.65 * np.abs(normals @ light)  # both faces of a shell are lit
    top = max(float(np.percentile(strain, 99)), 1e-12)
    cmap = plt.get_cmap("plasma")
    colours = cmap(0.1 + 0.85 * np.clip(strain / top, 0, 1))
    colours[:, :3] *= shade[:, None]
    fig = plt.figure(figsize=(6, 7))
    ax = fig.add_subplot(111, projection="3d")
    # edges in the faces' own colours close the seams the antialiasing leaves between them
    ax.add_collection3d(Poly3DCollection(triangles, facecolors=colours, edgecolors=colours,
                                         linewidths=0.3))
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    for axis, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        axis(c - half, c + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=np.degrees(k_elevation), azim=np.degrees(k_azimuth))
    ax.set_axis_off()
    mappable = plt.cm.ScalarMappable(
        cmap=plt.matplotlib.colors.ListedColormap(cmap(np.linspace(0.1, 0.95, 256))),
        norm=plt.Normalize(0, top))
    fig.colorbar(mappable, ax=ax, shrink=0.6, pad=0.0, label="equivalent plastic strain")
    if title:
        ax.set_title(title)
    fig.savefig(out, dpi=110, bbox_inches="tight")
    plt.close(fig)


def plot(results, out, x, y, x_scale, y_scale, x_label, y_label, title):
    data = fpmv.read_csv(os.path.join(results, "history.csv"))
    plt = fpmv.pyplot()
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.plot(np.asarray(data[x]) * x_scale, np.asarray(data[y]) * y_scale, lw=0.8)
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_label)
    if title:
        ax.set_title(title)
    ax.grid(alpha=0.3)
    fig.savefig(out, dpi=110, bbox_inches="tight")
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results")
    ap.add_argument("picture")
    ap.add_argument("--mirror", choices=["none", "xy"], default="none")
    ap.add_argument("--title", default="")
    ap.add_argument("--plot")
    ap.add_argument("--x")
    ap.add_argument("--y")
    ap.add_argument("--x-scale", type=float, default=1.0)
    ap.add_argument("--y-scale", type=float, default=1.0)
    ap.add_argument("--x-label", default="")
    ap.add_argument("--y-label", default="")
    ap.add_argument("--plot-title", default="")
    a = ap.parse_args()
    points, cells, strain = last_frame(a.results)
    if a.mirror == "xy":
        points, cells, strain = mirrored(points, cells, strain)
    render(points, cells, strain, a.picture, a.title, cull=a.mirror == "xy")
    print(a.picture)
    if a.plot:
        plot(a.results, a.plot, a.x, a.y, a.x_scale, a.y_scale, a.x_label or a.x,
             a.y_label or a.y, a.plot_title)
        print(a.plot)


if __name__ == "__main__":
    main()

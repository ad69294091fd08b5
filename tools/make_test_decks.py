#!/usr/bin/env python3
"""Writes the meshes of the test decks in examples/decks (NAME/NAME_mesh.k, included by
NAME/NAME.k): *NODE and *ELEMENT_SHELL cards in LS-DYNA's fixed columns, and the node sets
the decks name. The decks themselves and their YAML twins are written by hand.

    python3 tools/make_test_decks.py   # rewrites examples/decks/*/*_mesh.k
"""
import math
import pathlib

ROOT = pathlib.Path(__file__).resolve().parent.parent / "examples" / "decks"


def node_card(nid, x, y, z):
    return f"{nid:8d}{x:16.9g}{y:16.9g}{z:16.9g}{0:8d}{0:8d}"


def shell_card(eid, pid, n):
    return f"{eid:8d}{pid:8d}" + "".join(f"{k:8d}" for k in n)


def grid(nx, ny, point, first_node=1):
    """Nodes of an (nx+1) x (ny+1) grid, point(i, j) -> (x, y, z); ids row by row."""
    nodes, ids = [], {}
    nid = first_node
    for j in range(ny + 1):
        for i in range(nx + 1):
            ids[i, j] = nid
            nodes.append(node_card(nid, *point(i, j)))
            nid += 1
    return nodes, ids


def quads(nx, ny, ids, pid, first_element=1, wrap=False):
    cards, eid = [], first_element
    for j in range(ny):
        for i in range(nx):
            i1 = (i + 1) % nx if wrap else i + 1
            cards.append(shell_card(eid, pid, [ids[i, j], ids[i1, j], ids[i1, j + 1], ids[i, j + 1]]))
            eid += 1
    return cards


def node_set(sid, title, members):
    lines = ["*SET_NODE_LIST_TITLE", title, f"{sid:10d}"]
    for k in range(0, len(members), 8):
        lines.append("".join(f"{m:10d}" for m in members[k:k + 8]))
    return lines


def write(name, lines):
    path = ROOT / name / f"{name}_mesh.k"
    path.parent.mkdir(parents=True, exist_ok=True)
    head = ["*KEYWORD", f"$ mesh of {name}.k, written by tools/make_test_decks.py"]
    path.write_text("\n".join(head + lines + ["*END", ""]))


def plate_drop():
    # 100 x 100 mm plate, 8 x 8 quadrangles, tilted 10 degrees about x, lowest edge 3 mm above
    # the wall z = 0
    n, a, tilt = 8, 0.1, math.radians(10.0)
    nodes, ids = grid(n, n, lambda i, j: (a * i / n, a * j / n * math.cos(tilt),
                                          0.003 + a * j / n * math.sin(tilt)))
    write("plate_drop", ["*NODE"] + nodes + ["*ELEMENT_SHELL"] + quads(n, n, ids, 1))


def clamped_beam():
    # 200 x 20 mm strip, 20 x 2 quadrangles in the plane z = 0; the sets: both ends (clamped)
    # and the middle fifth (the impulse)
    nx, ny, lx, ly = 20, 2, 0.2, 0.02
    nodes, ids = grid(nx, ny, lambda i, j: (lx * i / nx, ly * j / ny, 0.0))
    ends = sorted(ids[i, j] for j in range(ny + 1) for i in (0, nx))
    middle = sorted(ids[i, j] for j in range(ny + 1) for i in range(8, 13))
    write("clamped_beam", ["*NODE"] + nodes + ["*ELEMENT_SHELL"] + quads(nx, ny, ids, 1) +
          node_set(1, "ends", ends) + node_set(2, "impulse", middle))


def tube_crush():
    # square tube 40 x 40 mm, 120 mm long along z, 4 quadrangles per face, 12 along; the
    # bottom ring is clamped node by node in the deck
    per_face, nz, w, length = 4, 12, 0.04, 0.12
    around = 4 * per_face

    def ring(k):
        face, s = divmod(k, per_face)
        t = -w / 2 + w * s / per_face
        return [(t, -w / 2), (w / 2, t), (-t, w / 2), (-w / 2, -t)][face]

    nodes, ids = [], {}
    nid = 1
    for j in range(nz + 1):
        for i in range(around):
            ids[i, j] = nid
            x, y = ring(i)
            nodes.append(node_card(nid, x, y, length * j / nz))
            nid += 1
    write("tube_crush", ["*NODE"] + nodes + ["*ELEMENT_SHELL"] +
          quads(around, nz, ids, 1, wrap=True))
    return [ids[i, 0] for i in range(around)]


def pressure_panel():
    # 300 x 300 mm panel, 10 x 10 quadrangles, clamped edges (a node set), loaded by a pressure
    # on all its shells (a shell set) and a point force at the centre
    n, a = 10, 0.3
    nodes, ids = grid(n, n, lambda i, j: (a * i / n, a * j / n, 0.0))
    edge = sorted({ids[i, j] for i in range(n + 1) for j in range(n + 1)
                   if i in (0, n) or j in (0, n)})
    shells = list(range(1, n * n + 1))
    lines = ["*NODE"] + nodes + ["*ELEMENT_SHELL"] + quads(n, n, ids, 1) + node_set(1, "edge", edge)
    lines += ["*SET_SHELL_LIST", f"{7:10d}"]
    for k in range(0, len(shells), 8):
        lines.append("".join(f"{m:10d}" for m in shells[k:k + 8]))
    write("pressure_panel", lines)


def strip_pull():
    # 100 x 10 mm strip, 20 x 2 quadrangles in the plane z = 0; node sets of its two ends
    nx, ny, lx, ly = 20, 2, 0.1, 0.01
    nodes, ids = grid(nx, ny, lambda i, j: (lx * i / nx, ly * j / ny, 0.0))
    write("strip_pull", ["*NODE"] + nodes + ["*ELEMENT_SHELL"] + quads(nx, ny, ids, 1) +
          node_set(1, "fixed_end", [ids[0, j] for j in range(ny + 1)]) +
          node_set(2, "pulled_end", [ids[nx, j] for j in range(ny + 1)]))


def plate_hammer():
    # a 100 x 100 mm plate (part 1, 8 x 8 quadrangles, nodes 1-81) 1.5 mm above the floor z = 0;
    # a 50 x 50 mm doubler (part 2, 4 x 4, nodes 101-125) 3.5 mm above its middle, its corners
    # over plate nodes 21, 25, 57, 61 (the spot welds); a 30 x 30 mm rigid hammer (part 3, 2 x 2,
    # nodes 201-209) 15 mm up; the node set of the plate's edge y = 0 (a nodal rigid body)
    n, a = 8, 0.1
    plate, ids = grid(n, n, lambda i, j: (a * i / n, a * j / n, 0.0015))
    doubler, dids = grid(4, 4, lambda i, j: (0.025 + 0.0125 * i, 0.025 + 0.0125 * j, 0.005),
                         first_node=101)
    hammer, hids = grid(2, 2, lambda i, j: (0.035 + 0.015 * i, 0.035 + 0.015 * j, 0.015),
                        first_node=201)
    write("plate_hammer", ["*NODE"] + plate + doubler + hammer + ["*ELEMENT_SHELL"] +
          quads(n, n, ids, 1) + quads(4, 4, dids, 2, first_element=101) +
          quads(2, 2, hids, 3, first_element=201) + node_set(1, "edge", [ids[i, 0] for i in range(n + 1)]))


def solid_card(eid, pid, n):
    return f"{eid:8d}{pid:8d}" + "".join(f"{k:8d}" for k in n)


def block_drop():
    # a 100 x 100 mm plate (part 1, 10 x 10 quadrangles, nodes 1-121) in z = 0, its edge a node
    # set; a rigid 40 x 40 x 40 mm block (part 2) 1.5 mm above it: 2 x 2 x 2 hexahedra (nodes
    # 201-227, node 214 inside), a roof of four pentahedra (N5 = N6, N7 = N8; ridges along y 10 mm
    # up, nodes 301-306; written in the two-card form) and a tetrahedron on one outer gable
    # (apex node 307)
    n, a = 10, 0.1
    plate, ids = grid(n, n, lambda i, j: (a * i / n, a * j / n, 0.0))
    edge = sorted(ids[i, j] for i in range(n + 1) for j in range(n + 1) if i in (0, n) or j in (0, n))
    xs, zs = [0.03, 0.05, 0.07], [0.0015, 0.0215, 0.0415]
    block, hid = [], {}
    for k in range(3):
        for j in range(3):
            for i in range(3):
                hid[i, j, k] = 201 + i + 3 * j + 9 * k
                block.append(node_card(hid[i, j, k], xs[i], xs[j], zs[k]))
    ridge = {}
    for r, (im, j) in enumerate((im, j) for im in range(2) for j in range(3)):
        ridge[im, j] = 301 + r
        block.append(node_card(ridge[im, j], 0.04 + 0.02 * im, xs[j], 0.0515))
    block.append(node_card(307, 0.04, 0.02, 0.045))
    solids, eid = [], 201
    for k in range(2):
        for j in range(2):
            for i in range(2):
                c = [hid[i, j, k], hid[i + 1, j, k], hid[i + 1, j + 1, k], hid[i, j + 1, k]]
                t = [hid[i, j, k + 1], hid[i + 1, j, k + 1], hid[i + 1, j + 1, k + 1],
                     hid[i, j + 1, k + 1]]
                solids.append(solid_card(eid, 2, c + t))
                eid += 1
    eid = 211
    for j in range(2):
        for i in range(2):
            base = [hid[i, j, 2], hid[i + 1, j, 2], hid[i + 1, j + 1, 2], hid[i, j + 1, 2]]
            top = [ridge[i, j], ridge[i, j], ridge[i, j + 1], ridge[i, j + 1]]
            solids += [f"{eid:8d}{2:8d}", "".join(f"{k:8d}" for k in base + top)]
            eid += 1
    tet = [hid[0, 0, 2], hid[1, 0, 2], ridge[0, 0], 307]
    solids.append(solid_card(221, 2, tet + [307] * 4))
    write("block_drop", ["*NODE"] + plate + block + ["*ELEMENT_SHELL"] + quads(n, n, ids, 1) +
          ["*ELEMENT_SOLID"] + solids + node_set(1, "edge", edge))


if __name__ == "__main__":
    plate_drop()
    clamped_beam()
    print("tube bottom ring:", tube_crush())
    pressure_panel()
    strip_pull()
    plate_hammer()
    block_drop()

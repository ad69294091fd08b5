"""The mesh of bench/whole_run/pressed_layers.yaml: two square layers of quadrilaterals, one above
the other (*NODE, *ELEMENT_SHELL), for crash_scaling.py and the MPI test (tests/mpi)."""


def write_layers_mesh(path, cells, width, gap):
    """Two layers of cells x cells quadrilaterals of side width / cells, the top one gap above the
    bottom one (their mid-surfaces)."""
    h = width / cells
    per = (cells + 1) ** 2
    with open(path, "w") as f:
        f.write("*KEYWORD\n*NODE\n")
        nid = 0
        for layer in (0, 1):
            for j in range(cells + 1):
                for i in range(cells + 1):
                    nid += 1
                    f.write("%8d%16.9g%16.9g%16.9g\n" % (nid, i * h, j * h, layer * gap))
        f.write("*ELEMENT_SHELL\n")
        eid = 0
        for layer in (0, 1):
            for j in range(cells):
                for i in range(cells):
                    eid += 1
                    n = layer * per + j * (cells + 1) + i + 1
                    f.write("%8d%8d%8d%8d%8d%8d\n" % (eid, 1, n, n + 1, n + cells + 2, n + cells + 1))
        f.write("*END\n")

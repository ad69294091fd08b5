# Eq. 6.4-3 (theory.md §6.4): the highest membrane frequency of small pieces of lumped-mass CST
# triangles against the step s L_c/c (s = 0.9, the default time_step_scale). Central
# differences are stable for omega dt < 2: a piece whose omega_max s L_c/c exceeds 2 diverges at
# that step, and needs the exact element step 2/omega_e (which bounds every assembly of its
# elements: assembled omega_max <= max element omega_e).
# Pieces of equilateral triangles (side 1, E = rho = 1, nu = 0.3): a lone triangle; two sharing
# a side (a rhombus); two sharing a corner only (a bow-tie); three in a row.
import math
from la import mat, mm, tr

NU = 0.3
C = [[1 / (1 - NU * NU), NU / (1 - NU * NU), 0], [NU / (1 - NU * NU), 1 / (1 - NU * NU), 0],
     [0, 0, 0.5 / (1 + NU)]]
WAVE = math.sqrt(1 / (1 - NU * NU))  # c = sqrt(E / (rho (1 - nu^2)))
H3 = math.sqrt(3) / 2


def element(xy):
    """CST stiffness (6 x 6, per unit thickness) and lumped corner mass of triangle xy."""
    cyc = [(0, 1, 2), (1, 2, 0), (2, 0, 1)]
    a2 = (xy[1][0] - xy[0][0]) * (xy[2][1] - xy[0][1]) - (xy[2][0] - xy[0][0]) * (xy[1][1] - xy[0][1])
    b = mat(3, 6)
    for i, j, k in cyc:
        bi, ci = (xy[j][1] - xy[k][1]) / a2, (xy[k][0] - xy[j][0]) / a2
        b[0][2 * i], b[1][2 * i + 1], b[2][2 * i], b[2][2 * i + 1] = bi, ci, ci, bi
    k = mm(tr(b), mm(C, b))
    return [[0.5 * a2 * v for v in row] for row in k], a2 / 6


def omega_max(nodes, triangles):
    """sqrt(lambda_max(M^-1 K)) of the assembled piece (power iteration on M^-1/2 K M^-1/2)."""
    n = 2 * len(nodes)
    kg, m = mat(n, n), [0.0] * n
    for t in triangles:
        ke, me = element([nodes[p] for p in t])
        for a in range(3):
            for da in range(2):
                m[2 * t[a] + da] += me
                for b in range(3):
                    for db in range(2):
                        kg[2 * t[a] + da][2 * t[b] + db] += ke[2 * a + da][2 * b + db]
    s = [[kg[i][j] / math.sqrt(m[i] * m[j]) for j in range(n)] for i in range(n)]
    v = [math.sin(1.3 * i + 0.7) for i in range(n)]
    lam = 0
    for _ in range(3000):
        w = [sum(s[i][j] * v[j] for j in range(n)) for i in range(n)]
        lam = math.sqrt(sum(x * x for x in w))
        v = [x / lam for x in w]
    return math.sqrt(lam)


STEP = 0.9 * H3 / WAVE  # s L_c / c, L_c = 2A / l_max = sqrt(3)/2
PIECES = {
    "lone triangle": ([(0, 0), (1, 0), (0.5, H3)], [(0, 1, 2)]),
    "two sharing a side": ([(0, 0), (1, 0), (0.5, H3), (1.5, H3)], [(0, 1, 2), (1, 3, 2)]),
    "two sharing a corner": ([(0, 0), (1, 0), (0.5, H3), (1.5, H3), (1, 2 * H3)],
                             [(0, 1, 2), (2, 3, 4)]),
    "three in a row": ([(0, 0), (1, 0), (0.5, H3), (1.5, H3), (1, 2 * H3)],
                       [(0, 1, 2), (1, 3, 2), (2, 3, 4)]),
}
if __name__ == "__main__":
    for name, (nodes, tris) in PIECES.items():
        w_dt = omega_max(nodes, tris) * STEP
        print("%-22s omega_max * 0.9 L_c/c = %.4f  (%s)" % (name, w_dt,
                                                            "unstable" if w_dt > 2 else "stable"))

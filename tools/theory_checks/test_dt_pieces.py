# Eq. 6.4-3 (theory.md §6.4): the highest membrane frequency of small pieces of lumped-mass CST
# triangles against the step s L_c/c (s = 0.9, the default time_step_scale). Central
# differences are stable for omega dt < 2: a piece whose omega_max s L_c/c exceeds 2 diverges at
# that step, and needs the exact element step 2/omega_e (which bounds every assembly of its
# elements: assembled omega_max <= max element omega_e).
# Pieces of equilateral triangles (side 1, E = rho = 1, nu = 0.3): a lone triangle; two sharing
# a side (a rhombus); two sharing a corner only (a bow-tie); three in a row.
# Then pieces of needles: 2 x 2 rectangles of 1 x a (a = 4, 5) cut into eight triangles round
# the centre. Three of them joined by sides, alone (a piece of the mesh as read): unstable at
# 0.9 L_c/c although the rule of eq. 6.4-3 stops at pieces of two. The whole eight with one
# triangle eroded: its mass stays on its particles (the FPM's erosion, theory.md §7.6), so the
# seven left are stable at 0.9 L_c/c; without that mass they would not be. (A wider sweep with
# numpy, not kept here: 6 x 6 meshes of three diagonal patterns, aspects 1 to 5 and shear, 10 to
# 60 % of the triangles eroded at random, masses kept: at most 1.89 with no rule at all.)
import itertools
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


def omega_max(nodes, triangles, massive=()):
    """sqrt(lambda_max(M^-1 K)) of the assembled piece (power iteration on M^-1/2 K M^-1/2);
    the triangles `massive` add their lumped mass and no stiffness (eroded)."""
    n = 2 * len(nodes)
    kg, m = mat(n, n), [0.0] * n
    for t in massive:
        me = element([nodes[p] for p in t])[1]
        for a in range(3):
            for da in range(2):
                m[2 * t[a] + da] += me
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


def needle_mesh(aspect):
    """The 2 x 2 rectangles of 1 x aspect (x of width 1/aspect), eight triangles round the
    centre particle 2."""
    nodes = [(x / aspect, y) for x, y in
             [(0, 0), (1, 0), (1, 1), (0, 1), (1, 2), (0, 2), (2, 0), (2, 1), (2, 2)]]
    tris = [(0, 1, 2), (0, 2, 3), (3, 2, 5), (2, 4, 5), (1, 6, 2), (6, 7, 2), (2, 7, 8), (2, 8, 4)]
    return nodes, tris


def lc_step(nodes, tris):
    """min over the elements of 0.9 L_c / c."""
    dt = float("inf")
    for t in tris:
        xy = [nodes[p] for p in t]
        a2 = (xy[1][0] - xy[0][0]) * (xy[2][1] - xy[0][1]) - \
             (xy[2][0] - xy[0][0]) * (xy[1][1] - xy[0][1])
        l_max = max(math.dist(xy[i], xy[(i + 1) % 3]) for i in range(3))
        dt = min(dt, 0.9 * (a2 / l_max) / WAVE)
    return dt


def alone(nodes, tris):
    """The piece `tris` with its own particles only, numbered afresh."""
    used = sorted({p for t in tris for p in t})
    new = {p: i for i, p in enumerate(used)}
    return [nodes[p] for p in used], [tuple(new[p] for p in t) for t in tris]


def joined(tris):
    """Whether the triangles are one piece joined by their sides."""
    side = lambda t: {frozenset((t[i], t[(i + 1) % 3])) for i in range(3)}
    seen, todo = {0}, [0]
    while todo:
        a = todo.pop()
        for b in range(len(tris)):
            if b not in seen and side(tris[a]) & side(tris[b]):
                seen.add(b)
                todo.append(b)
    return len(seen) == len(tris)


def verdict(w_dt):
    return "%.4f (%s)" % (w_dt, "unstable" if w_dt > 2 else "stable")


if __name__ == "__main__":
    for name, (nodes, tris) in PIECES.items():
        print("%-22s omega_max * 0.9 L_c/c = %s" % (name, verdict(omega_max(nodes, tris) * STEP)))
    nodes, tris = PIECES["three in a row"]
    print("three in a row, the middle one eroded, its mass kept: %s"
          % verdict(omega_max(nodes, [tris[0], tris[2]], [tris[1]]) * STEP))
    for aspect in (4, 5):
        nodes, tris = needle_mesh(aspect)
        # the worst three of them joined by sides, a piece as read
        three = max((list(c) for c in itertools.combinations(tris, 3) if joined(list(c))),
                    key=lambda c: omega_max(*alone(nodes, c)) * lc_step(*alone(nodes, c)))
        left = tris[:1] + tris[2:]  # the eighth, tris[1], eroded
        print("needles 1:%d  whole %s; three alone %s; one eroded, its mass kept %s, "
              "its mass gone %s" % (
                  aspect, verdict(omega_max(nodes, tris) * lc_step(nodes, tris)),
                  verdict(omega_max(*alone(nodes, three)) * lc_step(*alone(nodes, three))),
                  verdict(omega_max(nodes, left, [tris[1]]) * lc_step(nodes, left)),
                  verdict(omega_max(nodes, left) * lc_step(nodes, left))))

"""Independent checks of theory.md §6.13 (the air blast), standard library only.

1. The Kingery-Bulmash polynomials (eq. 6.13-1) in the report's imperial units, converted to
   SI here, against the check values of benchmarks.md §6.2 (free air and surface burst,
   Z = 0.5 ... 10 m/kg^(1/3)): the largest relative difference per burst.
2. The Friedlander pulse (eq. 6.13-3): its closed-form impulse P t0 (b - 1 + e^-b) / b^2
   against Simpson's rule, and the decay b solved from the fits' impulses by bisection (not the
   C++ Newton iteration) at Z = 0.5, 1, 2, 5, 10 of the free-air burst.
3. The angle law (eq. 6.13-4) at 0, 45, 90 degrees.
4. The negative phase (eq. 6.13-5): the continued curve's impulse past t0, -e^-b / b^2 per
   P t0, against Simpson's rule over 60 t0, and its deepest point e^-(1+b) / b.
Run: cd tools/theory_checks && /usr/bin/python3 test_blast.py
"""
import math

L = math.log10
Z_FT = 3.280839895013123 / 2.2046226218487757 ** (1 / 3)   # ft/lb^(1/3) per m/kg^(1/3)
PSI, T = 6894.757293168361, 2.2046226218487757 ** (1 / 3)  # Pa per psi; lb^(1/3) per kg^(1/3)


def poly(u_coef, y_coef, z):
    u = u_coef[0] + u_coef[1] * L(z * Z_FT)
    return 10 ** sum(c * u ** i for i, c in enumerate(y_coef))


def piece(pieces, z):
    zf = z * Z_FT
    chosen = pieces[0]
    for p in pieces:
        if zf >= p[0]:
            chosen = p
    return poly(chosen[1], chosen[2], z)


# (lower bound ft/lb^(1/3), U, Y) of each piece: Kingery & Bulmash 1984, imperial
FREE = {
    "pso": [(0.134, [-0.756579302, 1.3503425], [1.772849705, -1.690128014, 0.008049736, 0.336743115, -0.005162264, -0.080922862, -0.004785073, 0.007930305, 0.000768447])],
    "pr": [(0.134, [-0.756579302, 1.3503425], [2.391061349, -2.21400539, 0.035119031, 0.657599992, 0.014181895, -0.243076636, -0.01586998, 0.049274118, 0.002276396, -0.003971263])],
    "is": [(0.134, [1.045048777, 3.242990665], [1.435341365, -0.443749378, 0.168825415, 0.034813803, -0.010435193]),
           (2.0, [-2.679125195, 2.306292318], [0.599008468, -0.404632921, -0.014272195, 0.009123663, -0.000675068, -0.008008637, 0.003148195, 0.001520448, -0.000747027])],
    "ir": [(0.134, [-0.75765992, 1.37882996], [1.605792801, -0.903118886, 0.101771878, -0.024213975])],
    "ta": [(0.134, [-0.805017341, 1.374070438], [-0.042373394, 1.364568712, -0.057003569, -0.182832225, 0.011885144, 0.043264869, -0.000799737, -0.004360736])],
    "t0": [(0.37, [0.20944006, 5.115885543], [-0.801052723, 0.164953518, 0.127788499, 0.002914301, 0.001879574, 0.017341396, 0.002697398, -0.003619765, -0.001009266]),
           (2.24, [-5.067784938, 9.299628861], [0.115874238, -0.029794427, 0.030632954, 0.018340557, -0.017396467, -0.00106322, 0.0056206, 0.000161822, -0.000686019]),
           (5.75, [-4.395901341, 3.152472536], [0.506592104, 0.0967032, -0.008013021, 0.004827058, 0.001875873, -0.002467385, -0.000841117, 0.000619329])],
}
SURFACE = {
    "pso": [(0.17, [-0.756579302, 1.3503425], [1.942250201, -1.695898874, -0.154159377, 0.514060731, 0.098853437, -0.293912623, -0.026811235, 0.109097496, 0.001628468, -0.021463103, 0.000145672, 0.001678478])],
    "pr": [(0.17, [-0.789312406, 1.366377192], [2.564313211, -2.210308706, -0.218536586, 0.895319589, 0.249890098, -0.569249437, -0.117916824, 0.224131161, 0.024562026, -0.0455116, -0.001909307, 0.003614712])],
    "is": [(0.17, [0.832468843, 3.076032967], [1.571592406, -0.502992764, 0.171335645, 0.045017696, -0.011896463]),
           (2.41, [-2.913586168, 2.406977454], [0.719852656, -0.384519027, -0.026081671, 0.005957988, 0.014544526, -0.006632893, -0.002841893, 0.001364482])],
    "ir": [(0.17, [-0.781951689, 1.334220499], [1.752916778, -0.949516093, 0.112136119, -0.025065918])],
    "ta": [(0.17, [-0.755684473, 1.377842236], [-0.173607601, 1.357064963, 0.052492799, -0.196563954, -0.060177005, 0.069636027, 0.021529749, -0.016165893, -0.00232532, 0.001477521])],
}
UNIT = {"pso": PSI / 1e3, "pr": PSI / 1e3, "is": PSI * T / 1e3, "ir": PSI * T / 1e3, "ta": T, "t0": T}
# benchmarks.md 6.2: Z, Pso, Pr [kPa], is, ir [kPa ms/kg^(1/3)], ta, t0 [ms/kg^(1/3)]
TABLE_FREE = [(0.5, 3885, 3.036e4, 141.3, 1454, 0.1541, 0.320), (1, 934.9, 5006, 174.5, 559.0, 0.5318, 1.795),
              (2, 194.7, 645.8, 92.12, 235.7, 1.944, 1.846), (3, 81.59, 215.5, 64.33, 147.1, 3.987, 2.685),
              (5, 31.30, 70.02, 40.62, 83.32, 8.995, 3.333), (10, 11.09, 23.31, 21.13, 39.71, 22.72, 4.200)]
TABLE_SURFACE = [(0.5, 4888, 3.942e4, 166.2, 2371, 0.1432), (1, 1354, 8152, 236.3, 884.7, 0.4675),
                 (2, 283.7, 1058, 134.6, 363.8, 1.693), (3, 115.7, 330.7, 92.70, 224.3, 3.546),
                 (5, 43.23, 100.9, 59.31, 125.6, 8.242), (10, 14.89, 31.54, 31.04, 59.33, 21.66)]
KEYS = ["pso", "pr", "is", "ir", "ta", "t0"]


def worst(fits, table):
    w = 0
    for row in table:
        for key, ref in zip(KEYS, row[1:]):
            w = max(w, abs(piece(fits[key], row[0]) * UNIT[key] / ref - 1))
    return w


print("1. fits against benchmarks.md 6.2: free air %.2f %%, surface %.2f %%"
      % (100 * worst(FREE, TABLE_FREE), 100 * worst(SURFACE, TABLE_SURFACE)))


def ratio(b):
    return 0.5 - b / 6 if abs(b) < 1e-6 else (b - 1 + math.exp(-b)) / b ** 2


def simpson(b, n=20000):
    h = 1.0 / n
    f = [(1 - i * h) * math.exp(-b * i * h) for i in range(n + 1)]
    return h / 3 * (f[0] + f[-1] + 4 * sum(f[1:-1:2]) + 2 * sum(f[2:-1:2]))


closed = max(abs(simpson(b) / ratio(b) - 1) for b in (-2, -0.5, 0.1, 1, 3, 10, 30))
print("2. impulse of the unit pulse, closed form against Simpson: %.1e" % closed)
for z in (0.5, 1, 2, 5, 10):
    p, i, t0 = piece(FREE["pso"], z) * UNIT["pso"], piece(FREE["is"], z) * UNIT["is"], piece(FREE["t0"], z) * UNIT["t0"]
    target, lo, hi = i / (p * t0), -4.0, 1e4
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) > target else (lo, mid)
    b = 0.5 * (lo + hi)
    print("   Z = %4g: incident decay b = %.6f, pulse impulse / fit's = %.9f" % (z, b, simpson(b) * p * t0 / i))
c = math.sqrt(0.5)
for deg, cos, want in ((0, 1.0, 450), (45, c, 225 + 100 * c), (90, 0.0, 100)):
    got = 450 * cos * cos + 100 * (1 + cos - 2 * cos * cos)
    print("3. angle law at %2d deg (Pso 100, Pr 450): %.6f (expected %.6f)" % (deg, got, want))


def simpson_tail(b, n=60000, span=60.0):
    h = span / n
    f = [(1 - (1 + i * h)) * math.exp(-b * (1 + i * h)) for i in range(n + 1)]
    return h / 3 * (f[0] + f[-1] + 4 * sum(f[1:-1:2]) + 2 * sum(f[2:-1:2]))


tail = max(abs(simpson_tail(b) / (-math.exp(-b) / b ** 2) - 1) for b in (0.8, 2.5, 8.0))
deepest = max(abs(min((1 - u / 1000) * math.exp(-b * u / 1000) for u in range(1000, 60000))
                  / (-math.exp(-(1 + b)) / b) - 1) for b in (0.3, 0.8, 2.5))
print("4. negative phase: impulse closed form against Simpson %.1e; deepest point %.1e" % (tail, deepest))

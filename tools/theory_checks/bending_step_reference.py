"""Reference critical steps of one triangle's bending modes for
tests/unit/elements/test_bending_time_step.cpp (BendingCriticalStep.MatchesIndependentPython).

E = 1, nu = 0.3, rho = 1; lumped mass m = rho h A / 3 per node; rotary inertia
m h^2 / 12 (option A) or m (A / 8 + h^2 / 12) (option B); dt = 2 / omega_max of the 9-DOF
bending stiffness (theory.md sections 6.2, 6.4), found by power iteration (test_rot.py).
Prints one line per case of the test, dt to 8 digits.
"""
import math
from plate import B9_dkt, B9_bciz
from test_rot import K9, lam_max

E, nu, rho = 1.0, 0.3, 1.0
shapes = {'equilateral': [[0, 0], [1, 0], [0.5, math.sqrt(3) / 2]],
          'right': [[0, 0], [1, 0], [0, 1]]}
kernels = {'DKT': B9_dkt, 'BCIZ': B9_bciz}
# (shape, kernel, h, option B) in the order of the C++ test's table
cases = [('equilateral', 'DKT', 0.05, False), ('equilateral', 'DKT', 0.05, True),
         ('equilateral', 'DKT', 0.5, True), ('equilateral', 'DKT', 1.2, True),
         ('equilateral', 'BCIZ', 0.05, False), ('equilateral', 'BCIZ', 0.5, True),
         ('equilateral', 'BCIZ', 1.2, True), ('right', 'DKT', 0.5, False),
         ('right', 'DKT', 1.2, True), ('right', 'BCIZ', 0.05, True),
         ('right', 'BCIZ', 0.5, True), ('right', 'BCIZ', 1.2, False)]
for shape, kernel, h, option_b in cases:
    xy = shapes[shape]
    d = E * h**3 / (12 * (1 - nu * nu))
    db = [[d, nu * d, 0], [nu * d, d, 0], [0, 0, d * (1 - nu) / 2]]
    k, area = K9(xy, kernels[kernel], db)
    m = rho * h * area / 3
    j = m * ((area / 8 if option_b else 0.0) + h * h / 12)
    dt = 2 / math.sqrt(lam_max([m, j, j] * 3, k))
    print('%-11s %-4s h %-4g option %s  dt %.8f' % (shape, kernel, h, 'B' if option_b else 'A', dt))

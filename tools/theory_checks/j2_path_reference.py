"""Reference states for tests/unit/materials/test_j2_plastic.cpp
(J2Plastic.RandomPathMatchesThreeDimensionalReturnWithZeroSigma33).

The random non-proportional path of test_j2.py (60 strain increments, random.seed(0)),
integrated by the independent 3-D radial return with sigma_33 = 0 found by bisection
(r3d_ps). Prints every increment (17 digits) and, after increments 19, 39 and 59, the
plane-stress stress, back stress b = [2 beta11 + beta22, 2 beta22 + beta11, beta12] and
equivalent plastic strain (12 digits).
"""
import random
from test_j2 import r3d_ps

random.seed(0)
S = [[0] * 3 for _ in range(3)]
B = [[0] * 3 for _ in range(3)]
A = 0.0
for step in range(60):
    de = [random.uniform(-1, 1) * 4e-4 + (8e-4 if step < 20 else -6e-4),
          random.uniform(-1, 1) * 4e-4, random.uniform(-1, 1) * 6e-4]
    print('increment %2d: %.17g, %.17g, %.17g' % (step, de[0], de[1], de[2]))
    S, B, A = r3d_ps(S, B, A, de)
    if step in (19, 39, 59):
        sigma = [S[0][0], S[1][1], S[0][1]]
        b = [2 * B[0][0] + B[1][1], 2 * B[1][1] + B[0][0], B[0][1]]
        print('  state after %d: sigma %s  b %s  alpha %.12g' % (
            step, ', '.join('%.12g' % v for v in sigma), ', '.join('%.12g' % v for v in b), A))

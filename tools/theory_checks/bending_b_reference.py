"""Reference rotation-only bending B matrices for tests/unit/elements/test_triangle_shape.cpp
(Bending.MatricesMatchIndependentReference): the triangle (0,0), (1.3,0), (0.4,0.9); BCIZ
(theory.md section 4.3) at the area coordinates (2/3, 1/6, 1/6), DKT (section 4.7) at
(0.2, 0.5, 0.3). Prints each 3x6 matrix row by row, 17 significant digits.
"""
from plate import Bb_bciz, Bb_dkt

xy = [[0.0, 0.0], [1.3, 0.0], [0.4, 0.9]]
for name, b in (('BCIZ', Bb_bciz(xy, (2 / 3, 1 / 6, 1 / 6))), ('DKT', Bb_dkt(xy, 0.5, 0.3))):
    print(name)
    for row in b:
        print('  ' + ', '.join('%.17g' % v for v in row))

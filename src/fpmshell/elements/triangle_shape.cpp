#include "fpmshell/elements/triangle_shape.hpp"

#include "fpmshell/elements/bciz_curvature.hpp"
#include "fpmshell/elements/dkt_curvature.hpp"

namespace fpmshell {
namespace {

constexpr std::array<std::array<int, 3>, 3> k_cyclic{{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}}};

Mat36 to_mat36(const std::array<std::array<Real, 6>, 3>& rows) {
    Mat36 m;
    for (Eigen::Index r = 0; r < 3; ++r)
        for (Eigen::Index q = 0; q < 6; ++q)
            m(r, q) = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(q)];
    return m;
}

}  // namespace

TriangleShape::TriangleShape(Real x2, Real x3, Real y3)
    : x{0, x2, x3}, y{0, 0, y3}, two_area(x2 * y3) {
    for (const auto& [i, j, k] : k_cyclic) {
        b[i] = y[j] - y[k];
        c[i] = x[k] - x[j];
    }
}

Mat36 bending_b_bciz(const TriangleShape& s, const std::array<Real, 3>& L) {
    const auto rows = bciz_curvature(L, s.b, s.c, -1.0 / (s.two_area * s.two_area));  // §4.2-§4.3
    return to_mat36(rows);
}

Mat36 bending_b_dkt(const TriangleShape& s, const std::array<Real, 3>& L) {
    const Real x2 = s.x[1], x3 = s.x[2], y3 = s.y[2];
    const auto rows =
        dkt_curvature(dkt_derivatives(L), dkt_sides(x2, x3, y3), x2, x3, y3, 1.0 / s.two_area);
    return to_mat36(rows);
}

}  // namespace fpmshell

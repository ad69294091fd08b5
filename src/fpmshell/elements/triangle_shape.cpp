#include "fpmshell/elements/triangle_shape.hpp"

#include "fpmshell/elements/bciz_curvature.hpp"

namespace fpmshell {
namespace {

constexpr std::array<std::array<int, 3>, 3> k_cyclic{{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}}};

}  // namespace

TriangleShape::TriangleShape(Real x2, Real x3, Real y3)
    : x{0, x2, x3}, y{0, 0, y3}, two_area(x2 * y3) {
    for (const auto& [i, j, k] : k_cyclic) {
        b[i] = y[j] - y[k];
        c[i] = x[k] - x[j];
    }
}

Mat36 membrane_b(const TriangleShape& s) {
    Mat36 bm = Mat36::Zero();
    for (int i = 0; i < 3; ++i) {
        bm(0, 2 * i) = s.b[i];
        bm(1, 2 * i + 1) = s.c[i];
        bm(2, 2 * i) = s.c[i];
        bm(2, 2 * i + 1) = s.b[i];
    }
    return bm / s.two_area;
}

Mat36 bending_b_bciz(const TriangleShape& s, const std::array<Real, 3>& L) {
    const auto rows = bciz_curvature(L, s.b, s.c, -1.0 / (s.two_area * s.two_area));  // §4.2-§4.3
    Mat36 bb;
    for (Eigen::Index r = 0; r < 3; ++r)
        for (Eigen::Index q = 0; q < 6; ++q)
            bb(r, q) = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(q)];
    return bb;
}

DktShape dkt_shape(const TriangleShape& s) {
    // Sides k = 4, 5, 6 <-> ij = 23, 31, 12 (theory.md §4.7).
    constexpr std::array<std::array<int, 2>, 3> side{{{1, 2}, {2, 0}, {0, 1}}};
    DktShape d;
    for (std::size_t m = 0; m < 3; ++m) {
        const Real xij =
            s.x[static_cast<std::size_t>(side[m][0])] - s.x[static_cast<std::size_t>(side[m][1])];
        const Real yij =
            s.y[static_cast<std::size_t>(side[m][0])] - s.y[static_cast<std::size_t>(side[m][1])];
        const Real inv_l2 = 1.0 / (xij * xij + yij * yij);
        d.cb[m] = 0.75 * xij * yij * inv_l2;
        d.cc[m] = (0.25 * xij * xij - 0.5 * yij * yij) * inv_l2;
        d.ce[m] = (0.25 * yij * yij - 0.5 * xij * xij) * inv_l2;
    }
    d.x31 = s.x[2] - s.x[0];
    d.y31 = s.y[2] - s.y[0];
    d.x12 = s.x[0] - s.x[1];
    d.y12 = s.y[0] - s.y[1];
    d.inv_two_area = 1.0 / (d.x31 * d.y12 - d.x12 * d.y31);
    return d;
}

Mat36 bending_b_dkt(const DktShape& d, const std::array<Real, 3>& L) {
    const auto& cb = d.cb;
    const auto& cc = d.cc;
    const auto& ce = d.ce;
    const Real xi = L[1], eta = L[2];
    const std::array<Real, 6> n_xi{-3 + 4 * xi + 4 * eta, 4 * xi - 1, 0.0, 4 * eta, -4 * eta,
                                   4 * (1 - 2 * xi - eta)};
    const std::array<Real, 6> n_eta{-3 + 4 * xi + 4 * eta,  0.0,    4 * eta - 1, 4 * xi,
                                    4 * (1 - xi - 2 * eta), -4 * xi};
    // Hx, Hy at the rotation DOFs [thx1 thy1 thx2 thy2 thx3 thy3] (the w columns are dropped:
    // the deformation deflections are zero) evaluated on derivative arrays N.
    auto h_of = [&](const std::array<Real, 6>& n, std::array<Real, 6>& hx,
                    std::array<Real, 6>& hy) {
        const Real n1 = n[0], n2 = n[1], n3 = n[2], n4 = n[3], n5 = n[4], n6 = n[5];
        // index m: 0 <-> side 4, 1 <-> side 5, 2 <-> side 6
        hx = {cb[1] * n5 + cb[2] * n6, n1 - cc[1] * n5 - cc[2] * n6,
              cb[2] * n6 + cb[0] * n4, n2 - cc[2] * n6 - cc[0] * n4,
              cb[0] * n4 + cb[1] * n5, n3 - cc[0] * n4 - cc[1] * n5};
        hy = {-n1 + ce[1] * n5 + ce[2] * n6, -cb[1] * n5 - cb[2] * n6,
              -n2 + ce[2] * n6 + ce[0] * n4, -cb[2] * n6 - cb[0] * n4,
              -n3 + ce[0] * n4 + ce[1] * n5, -cb[0] * n4 - cb[1] * n5};
    };
    std::array<Real, 6> hx_xi, hy_xi, hx_eta, hy_eta;
    h_of(n_xi, hx_xi, hy_xi);
    h_of(n_eta, hx_eta, hy_eta);
    const Real f = d.inv_two_area;
    Mat36 bb;
    for (std::size_t q = 0; q < 6; ++q) {
        const Eigen::Index col = static_cast<Eigen::Index>(q);
        bb(0, col) = (d.y31 * hx_xi[q] + d.y12 * hx_eta[q]) * f;
        bb(1, col) = (-d.x31 * hy_xi[q] - d.x12 * hy_eta[q]) * f;
        bb(2, col) =
            (-d.x31 * hx_xi[q] - d.x12 * hx_eta[q] + d.y31 * hy_xi[q] + d.y12 * hy_eta[q]) * f;
    }
    return bb;
}

}  // namespace fpmshell

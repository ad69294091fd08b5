#include "fpmshell/elements/triangle_shape.hpp"

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
    // Second derivatives in closed form (theory.md §4.3): for u, v in {b, c},
    //   u.H(g_ij).v = 2 L_j u_i v_i + 2 L_i (u_i v_j + u_j v_i)       (g_ij = L_i^2 L_j)
    //   u.H(B).v    = L3 (u1 v2 + u2 v1) + L2 (u1 v3 + u3 v1) + L1 (u2 v3 + u3 v2)
    // and f,xx = b.H.b / (2A)^2, f,yy = c.H.c / (2A)^2, f,xy = b.H.c / (2A)^2.
    const auto& b = s.b;
    const auto& c = s.c;
    auto q_g = [&L](int i, int j, const std::array<Real, 3>& u, const std::array<Real, 3>& v) {
        return 2 * L[j] * u[i] * v[i] + 2 * L[i] * (u[i] * v[j] + u[j] * v[i]);
    };
    auto q_bubble = [&L](const std::array<Real, 3>& u, const std::array<Real, 3>& v) {
        return L[2] * (u[0] * v[1] + u[1] * v[0]) + L[1] * (u[0] * v[2] + u[2] * v[0]) +
               L[0] * (u[1] * v[2] + u[2] * v[1]);
    };
    const Real f = -1.0 / (s.two_area * s.two_area);
    const Real bub_bb = q_bubble(b, b), bub_cc = q_bubble(c, c), bub_bc = q_bubble(b, c);
    Mat36 bb;
    for (const auto& [i, j, k] : k_cyclic) {
        const Real gik_bb = q_g(i, k, b, b), gik_cc = q_g(i, k, c, c), gik_bc = q_g(i, k, b, c);
        const Real gij_bb = q_g(i, j, b, b), gij_cc = q_g(i, j, c, c), gij_bc = q_g(i, j, b, c);
        // N_i^thx = b_j g_ik - b_k g_ij + (b_j - b_k)/2 B; N_i^thy likewise with c (§4.2).
        for (int col = 0; col < 2; ++col) {
            const auto& w = col == 0 ? b : c;
            const Real hb = 0.5 * (w[j] - w[k]);
            bb(0, 2 * i + col) = f * (w[j] * gik_bb - w[k] * gij_bb + hb * bub_bb);
            bb(1, 2 * i + col) = f * (w[j] * gik_cc - w[k] * gij_cc + hb * bub_cc);
            bb(2, 2 * i + col) = 2 * f * (w[j] * gik_bc - w[k] * gij_bc + hb * bub_bc);
        }
    }
    return bb;
}

Mat36 bending_b_dkt(const TriangleShape& s, const std::array<Real, 3>& L) {
    // Sides k = 4, 5, 6 <-> ij = 23, 31, 12 (theory.md §4.7).
    const std::array<std::array<int, 2>, 3> side{{{1, 2}, {2, 0}, {0, 1}}};
    std::array<Real, 3> ca, cb, cc, cd, ce;
    for (int m = 0; m < 3; ++m) {
        const Real xij = s.x[side[m][0]] - s.x[side[m][1]];
        const Real yij = s.y[side[m][0]] - s.y[side[m][1]];
        const Real l2 = xij * xij + yij * yij;
        ca[m] = -xij / l2;
        cb[m] = 0.75 * xij * yij / l2;
        cc[m] = (0.25 * xij * xij - 0.5 * yij * yij) / l2;
        cd[m] = -yij / l2;
        ce[m] = (0.25 * yij * yij - 0.5 * xij * xij) / l2;
    }
    const Real xi = L[1], eta = L[2];
    const std::array<Real, 6> n_xi{-3 + 4 * xi + 4 * eta, 4 * xi - 1, 0.0, 4 * eta, -4 * eta,
                                   4 * (1 - 2 * xi - eta)};
    const std::array<Real, 6> n_eta{-3 + 4 * xi + 4 * eta, 0.0, 4 * eta - 1, 4 * xi,
                                    4 * (1 - xi - 2 * eta), -4 * xi};
    // Hx, Hy (9 entries, DOFs [w1 thx1 thy1 w2 ...]) evaluated on derivative arrays N.
    auto h_of = [&](const std::array<Real, 6>& n, std::array<Real, 9>& hx, std::array<Real, 9>& hy) {
        const Real n1 = n[0], n2 = n[1], n3 = n[2], n4 = n[3], n5 = n[4], n6 = n[5];
        // index m: 0 <-> side 4, 1 <-> side 5, 2 <-> side 6
        hx = {1.5 * (ca[2] * n6 - ca[1] * n5), cb[1] * n5 + cb[2] * n6, n1 - cc[1] * n5 - cc[2] * n6,
              1.5 * (ca[0] * n4 - ca[2] * n6), cb[2] * n6 + cb[0] * n4, n2 - cc[2] * n6 - cc[0] * n4,
              1.5 * (ca[1] * n5 - ca[0] * n4), cb[0] * n4 + cb[1] * n5, n3 - cc[0] * n4 - cc[1] * n5};
        hy = {1.5 * (cd[2] * n6 - cd[1] * n5), -n1 + ce[1] * n5 + ce[2] * n6, -cb[1] * n5 - cb[2] * n6,
              1.5 * (cd[0] * n4 - cd[2] * n6), -n2 + ce[2] * n6 + ce[0] * n4, -cb[2] * n6 - cb[0] * n4,
              1.5 * (cd[1] * n5 - cd[0] * n4), -n3 + ce[0] * n4 + ce[1] * n5, -cb[0] * n4 - cb[1] * n5};
    };
    std::array<Real, 9> hx_xi, hy_xi, hx_eta, hy_eta;
    h_of(n_xi, hx_xi, hy_xi);
    h_of(n_eta, hx_eta, hy_eta);
    const Real x31 = s.x[2] - s.x[0], y31 = s.y[2] - s.y[0];
    const Real x12 = s.x[0] - s.x[1], y12 = s.y[0] - s.y[1];
    const Real a2 = x31 * y12 - x12 * y31;
    constexpr std::array<int, 6> k_rot_cols{1, 2, 4, 5, 7, 8};  // w columns dropped (w_i = 0)
    Mat36 bb;
    for (int q = 0; q < 6; ++q) {
        const int m = k_rot_cols[q];
        bb(0, q) = (y31 * hx_xi[m] + y12 * hx_eta[m]) / a2;
        bb(1, q) = (-x31 * hy_xi[m] - x12 * hy_eta[m]) / a2;
        bb(2, q) = (-x31 * hx_xi[m] - x12 * hx_eta[m] + y31 * hy_xi[m] + y12 * hy_eta[m]) / a2;
    }
    return bb;
}

}  // namespace fpmshell

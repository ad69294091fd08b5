#include "fpmshell/elements/membrane_time_step.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace fpmshell {

Real membrane_step_ratio(const TriangleShape& s, const Mat3& elasticity) {
    const Real longest = std::sqrt(
        std::max({s.x[1] * s.x[1], (s.x[2] - s.x[1]) * (s.x[2] - s.x[1]) + s.y[2] * s.y[2],
                  s.x[2] * s.x[2] + s.y[2] * s.y[2]}));
    if (!(s.two_area > 0) || !(longest > 0) || !(elasticity(0, 0) > 0))
        return std::numeric_limits<Real>::infinity();
    // B B^T of the CST (rows exx, eyy, gxy; columns [u_i, v_i]) with B = [b_i 0; 0 c_i; c_i b_i]
    // / 2A (theory.md §3.1)
    Mat3 bbt = Mat3::Zero();
    for (int i = 0; i < 3; ++i) {
        const Real b = s.b[static_cast<std::size_t>(i)], c = s.c[static_cast<std::size_t>(i)];
        bbt(0, 0) += b * b;
        bbt(1, 1) += c * c;
        bbt(2, 2) += c * c + b * b;
        bbt(0, 2) += b * c;
        bbt(1, 2) += c * b;
    }
    bbt(2, 0) = bbt(0, 2);
    bbt(2, 1) = bbt(1, 2);
    bbt /= s.two_area * s.two_area;
    // lambda(B B^T C) = lambda(L^T B B^T L), C / C_11 = L L^T: a symmetric 3 x 3 eigenproblem
    const Mat3 c_hat = elasticity / elasticity(0, 0);
    const Eigen::LLT<Mat3> llt(c_hat);
    const Mat3 l = llt.matrixL();
    const Real lambda =
        Eigen::SelfAdjointEigenSolver<Mat3>(l.transpose() * bbt * l, Eigen::EigenvaluesOnly)
            .eigenvalues()
            .maxCoeff();
    const Real lc = s.two_area / longest;
    return 2.0 / (lc * std::sqrt(3.0 * lambda));
}

}  // namespace fpmshell

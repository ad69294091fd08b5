#include "fpmshell/elements/bending_time_step.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "fpmshell/elements/shell_triangle.hpp"

namespace fpmshell {

Mat99 bending_stiffness_9dof(BendingKernel kernel, const TriangleShape& s,
                             const Eigen::Matrix<Real, 3, 3>& bending_rigidity) {
    // P maps [w, thx, thy] per node to the 6 deformation rotations: thx_i - w,y and
    // thy_i + w,x with w,x = sum b_k w_k / 2A, w,y = sum c_k w_k / 2A (§3.1 geometry).
    Eigen::Matrix<Real, 6, 9> p = Eigen::Matrix<Real, 6, 9>::Zero();
    for (int i = 0; i < 3; ++i) {
        p(2 * i, 3 * i + 1) = 1;
        p(2 * i + 1, 3 * i + 2) = 1;
        for (int k = 0; k < 3; ++k) {
            p(2 * i, 3 * k) = -s.c[static_cast<std::size_t>(k)] / s.two_area;
            p(2 * i + 1, 3 * k) = s.b[static_cast<std::size_t>(k)] / s.two_area;
        }
    }
    constexpr Real sixth = 1.0 / 6.0;
    constexpr Real two_thirds = 2.0 / 3.0;
    const std::array<std::array<Real, 3>, 3> points{
        {{two_thirds, sixth, sixth}, {sixth, two_thirds, sixth}, {sixth, sixth, two_thirds}}};
    Mat99 k = Mat99::Zero();
    const Real weight = 0.5 * s.two_area / 3.0;
    for (const auto& L : points) {
        const Eigen::Matrix<Real, 3, 9> b9 = bending_b(kernel, s, L) * p;
        k += weight * b9.transpose() * bending_rigidity * b9;
    }
    return k;
}

Real bending_critical_dt(BendingKernel kernel, const TriangleShape& s,
                         const Eigen::Matrix<Real, 3, 3>& bending_rigidity, Real node_mass,
                         Real node_inertia, Real sufficient) {
    if (!(s.two_area > 0) || !(node_mass > 0) || !(node_inertia > 0))
        return std::numeric_limits<Real>::infinity();
    Eigen::Matrix<Real, 9, 1> inv_sqrt_mass;
    for (int i = 0; i < 3; ++i) {
        inv_sqrt_mass(3 * i) = 1.0 / std::sqrt(node_mass);
        inv_sqrt_mass(3 * i + 1) = inv_sqrt_mass(3 * i + 2) = 1.0 / std::sqrt(node_inertia);
    }
    const Mat99 scaled = inv_sqrt_mass.asDiagonal() *
                         bending_stiffness_9dof(kernel, s, bending_rigidity) *
                         inv_sqrt_mass.asDiagonal();
    // The matrix is symmetric positive semi-definite: omega_max^2 = lambda_max <= sqrt(sum of
    // lambda^2) = its Frobenius norm, within sqrt(6) of lambda_max (6 bending modes).
    const Real omega2_bound = scaled.norm();
    if (omega2_bound > 0 && 2.0 / std::sqrt(omega2_bound) >= sufficient)
        return 2.0 / std::sqrt(omega2_bound);
    const Eigen::SelfAdjointEigenSolver<Mat99> eig(scaled, Eigen::EigenvaluesOnly);
    const Real omega2 = eig.eigenvalues().maxCoeff();
    return omega2 > 0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<Real>::infinity();
}

}  // namespace fpmshell

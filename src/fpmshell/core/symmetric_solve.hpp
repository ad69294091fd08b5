// x = A^+ b for a symmetric positive semi-definite 3 x 3 A: by its eigen-decomposition, the
// directions whose eigenvalue is below 1e-12 of the largest left out (a rigid body's inertia about
// a rotation nothing resists, the spread of particles that lie in a plane).
#pragma once

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

[[nodiscard]] inline Vec3 symmetric_pseudo_solve(const Mat3& a, const Vec3& b) {
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(a);
    const Vec3 values = eigen.eigenvalues();
    const Real floor = 1e-12 * std::max(values.maxCoeff(), Real(0));
    Vec3 projected = eigen.eigenvectors().transpose() * b;
    for (int k = 0; k < 3; ++k) projected[k] = values[k] > floor ? projected[k] / values[k] : 0;
    return eigen.eigenvectors() * projected;
}

}  // namespace fpmshell

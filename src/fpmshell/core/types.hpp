// Basic numeric types shared by every module of fpmshell.
#pragma once

#include <Eigen/Dense>
#include <cstdint>

namespace fpmshell {

/// Floating-point type of all physics (a float build could be tried by changing this line).
using Real = double;
/// Index of a particle, element or set member.
using Index = std::int32_t;

using Vec2 = Eigen::Matrix<Real, 2, 1>;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;
using Quat = Eigen::Quaternion<Real>;
/// Plane-stress Voigt vector: stress [sxx, syy, sxy] or strain [exx, eyy, gxy] (engineering shear).
using Voigt3 = Eigen::Matrix<Real, 3, 1>;

}  // namespace fpmshell

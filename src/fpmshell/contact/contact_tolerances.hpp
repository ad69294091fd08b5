// Tolerances of the contact's closest points and passes that both its pair search
// (contact_pair_search.cpp) and its sweeps (contact_solver.cpp) take (theory.md §8.1, §8.3).
#pragma once

#include <cstddef>

#include "fpmshell/core/types.hpp"

namespace fpmshell::contact_tolerances {

constexpr Real k_face_tolerance = 0.02;  // theory.md §8.1: barycentric weights >= -0.02
// A pass over the constraints (copy, weights, penetrations) costs tens of ns per constraint:
// it runs in parallel from this many times the sweeps' minimum (on the tube's ~1 400 constraints
// a parallel region per pass cost more than it shared out on two threads).
constexpr std::size_t k_pass_factor = 4;

/// The unit normal of the triangle a, b, c (zero for a degenerate one).
inline Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const Real len = n.norm();
    return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

}  // namespace fpmshell::contact_tolerances

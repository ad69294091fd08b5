// Integration rules of the shell element (theory.md §4.5): in-plane rules on the triangle in
// area coordinates, through-thickness rules on zeta in [-1, 1].
#pragma once

#include <array>
#include <span>
#include <stdexcept>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct TrianglePoint {
    std::array<Real, 3> L;  ///< area coordinates
    Real weight;            ///< weights sum to 1 (multiply by the area)
};

struct ThicknessPoint {
    Real zeta;    ///< position in [-1, 1]; z = zeta h / 2
    Real weight;  ///< weights sum to 2
};

/// 3-point (degree 2) or 7-point (degree 5, Radon) rule, theory.md §4.5 table.
[[nodiscard]] std::span<const TrianglePoint> triangle_rule(int n_points);
/// 2-point Gauss, or 3- / 5-point Lobatto (surface points zeta = +-1 included).
[[nodiscard]] std::span<const ThicknessPoint> thickness_rule(int n_points);

}  // namespace fpmshell

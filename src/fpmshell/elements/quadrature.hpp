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
/// The most points a rule through the thickness has (LS-DYNA's Gauss and Lobatto rules: 10).
inline constexpr int k_max_thickness_points = 10;

/// Gauss-Legendre through the thickness, 1 to 10 points (theory.md §4.5; LS-DYNA's NIP).
[[nodiscard]] std::span<const ThicknessPoint> gauss_thickness_rule(int n_points);
/// Gauss-Lobatto, 3 to 10 points: the surfaces zeta = +-1 included, so they yield first.
[[nodiscard]] std::span<const ThicknessPoint> lobatto_thickness_rule(int n_points);
/// The default rule of a number of points: Gauss for 1 and 2, Lobatto for 3 and more
/// (model-format.md `thickness_rule`).
[[nodiscard]] std::span<const ThicknessPoint> thickness_rule(int n_points);

}  // namespace fpmshell

#include "fpmshell/elements/quadrature.hpp"

#include <cmath>
#include <string>

namespace fpmshell {
namespace {

constexpr Real k_third = 1.0 / 3.0;

const std::array<TrianglePoint, 3> k_tri3{{
    {{2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0}, k_third},
    {{1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0}, k_third},
    {{1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0}, k_third},
}};

std::array<TrianglePoint, 7> make_tri7() {
    const Real s15 = std::sqrt(15.0);
    const Real a = (6.0 - s15) / 21.0, b = (6.0 + s15) / 21.0;
    const Real wa = (155.0 - s15) / 1200.0, wb = (155.0 + s15) / 1200.0;
    return {{
        {{k_third, k_third, k_third}, 9.0 / 40.0},
        {{a, a, 1 - 2 * a}, wa},
        {{a, 1 - 2 * a, a}, wa},
        {{1 - 2 * a, a, a}, wa},
        {{b, b, 1 - 2 * b}, wb},
        {{b, 1 - 2 * b, b}, wb},
        {{1 - 2 * b, b, b}, wb},
    }};
}
const std::array<TrianglePoint, 7> k_tri7 = make_tri7();

const std::array<ThicknessPoint, 2> k_gauss2{
    {{-1.0 / std::sqrt(3.0), 1.0}, {1.0 / std::sqrt(3.0), 1.0}}};
const std::array<ThicknessPoint, 3> k_lobatto3{
    {{-1.0, 1.0 / 3.0}, {0.0, 4.0 / 3.0}, {1.0, 1.0 / 3.0}}};
const std::array<ThicknessPoint, 5> k_lobatto5{{{-1.0, 0.1},
                                                {-std::sqrt(3.0 / 7.0), 49.0 / 90.0},
                                                {0.0, 32.0 / 45.0},
                                                {std::sqrt(3.0 / 7.0), 49.0 / 90.0},
                                                {1.0, 0.1}}};

}  // namespace

std::span<const TrianglePoint> triangle_rule(int n_points) {
    if (n_points == 3) return k_tri3;
    if (n_points == 7) return k_tri7;
    throw std::invalid_argument("in-plane rule with " + std::to_string(n_points) +
                                " points does not exist (3 or 7)");
}

std::span<const ThicknessPoint> thickness_rule(int n_points) {
    if (n_points == 2) return k_gauss2;
    if (n_points == 3) return k_lobatto3;
    if (n_points == 5) return k_lobatto5;
    throw std::invalid_argument("thickness rule with " + std::to_string(n_points) +
                                " points does not exist (2, 3 or 5)");
}

}  // namespace fpmshell

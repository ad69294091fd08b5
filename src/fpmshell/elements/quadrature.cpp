#include "fpmshell/elements/quadrature.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

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

// Closed forms of the rules the examples' results were computed with (their bytes kept): 2 Gauss
// points, 3 and 5 Lobatto points. The others are computed below to full precision.
const std::array<ThicknessPoint, 2> k_gauss2{
    {{-1.0 / std::sqrt(3.0), 1.0}, {1.0 / std::sqrt(3.0), 1.0}}};
const std::array<ThicknessPoint, 3> k_lobatto3{
    {{-1.0, 1.0 / 3.0}, {0.0, 4.0 / 3.0}, {1.0, 1.0 / 3.0}}};
const std::array<ThicknessPoint, 5> k_lobatto5{{{-1.0, 0.1},
                                                {-std::sqrt(3.0 / 7.0), 49.0 / 90.0},
                                                {0.0, 32.0 / 45.0},
                                                {std::sqrt(3.0 / 7.0), 49.0 / 90.0},
                                                {1.0, 0.1}}};

/// Legendre polynomial P_m(x) and its derivative, by the three-term recurrence.
std::pair<Real, Real> legendre(int m, Real x) {
    Real p0 = 1, p1 = x;
    if (m == 0) return {1.0, 0.0};
    for (int k = 2; k <= m; ++k) {
        const Real p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    // (1 - x^2) P_m' = m (P_{m-1} - x P_m), valid inside (-1, 1)
    return {p1, m * (p0 - x * p1) / (1 - x * x)};
}

/// Newton's iteration to the root of f near x0, f returning (f, f').
template <class F>
Real newton_root(F f, Real x) {
    for (int it = 0; it < 100; ++it) {
        const auto [v, d] = f(x);
        const Real dx = v / d;
        x -= dx;
        if (std::abs(dx) < 1e-16) break;
    }
    return x;
}

/// The rule from its points of zeta >= 0 (in decreasing zeta), mirrored so that it is exactly
/// symmetric about the mid-surface: ascending zeta, as the tables above.
std::vector<ThicknessPoint> mirrored(const std::vector<ThicknessPoint>& upper, int n) {
    std::vector<ThicknessPoint> rule(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < upper.size(); ++i) {
        rule[rule.size() - 1 - i] = upper[i];
        rule[i] = {-upper[i].zeta, upper[i].weight};
    }
    if (n % 2 == 1) rule[rule.size() / 2].zeta = 0;
    return rule;
}

/// Gauss-Legendre: the n roots of P_n, weights 2 / ((1 - x^2) P_n'(x)^2) (Abramowitz & Stegun
/// 25.4.29).
std::vector<ThicknessPoint> make_gauss(int n) {
    std::vector<ThicknessPoint> upper;
    for (int i = 1; i <= (n + 1) / 2; ++i) {
        const Real guess = std::cos(M_PI * (i - 0.25) / (n + 0.5));
        const Real x = n % 2 == 1 && i == (n + 1) / 2
                           ? 0.0
                           : newton_root([n](Real y) { return legendre(n, y); }, guess);
        const Real d = legendre(n, x).second;
        upper.push_back({x, 2 / ((1 - x * x) * d * d)});
    }
    return mirrored(upper, n);
}

/// Gauss-Lobatto: zeta = +-1 and the n - 2 roots of P_{n-1}', weights 2 / (n (n - 1) P_{n-1}^2)
/// (Abramowitz & Stegun 25.4.32).
std::vector<ThicknessPoint> make_lobatto(int n) {
    const int m = n - 1;
    const Real end_weight = 2.0 / (n * m);
    std::vector<ThicknessPoint> upper{{1.0, end_weight}};
    for (int i = 1; i <= (n - 1) / 2; ++i) {
        const Real guess = std::cos(M_PI * i / m);
        // f = P_m', f' = P_m'' = (2 x P_m' - m (m + 1) P_m) / (1 - x^2) (Legendre's equation)
        const auto f = [m](Real y) {
            const auto [p, d] = legendre(m, y);
            return std::pair<Real, Real>{d, (2 * y * d - m * (m + 1) * p) / (1 - y * y)};
        };
        const Real x = n % 2 == 1 && i == (n - 1) / 2 ? 0.0 : newton_root(f, guess);
        const Real p = legendre(m, x).first;
        upper.push_back({x, end_weight / (p * p)});
    }
    return mirrored(upper, n);
}

/// Every rule of both families, index n - 1 (n = 1 ... k_max_thickness_points).
struct ThicknessRules {
    std::array<std::vector<ThicknessPoint>, k_max_thickness_points> gauss, lobatto;
    ThicknessRules() {
        for (int n = 1; n <= k_max_thickness_points; ++n) {
            gauss[static_cast<std::size_t>(n - 1)] = make_gauss(n);
            if (n >= 3) lobatto[static_cast<std::size_t>(n - 1)] = make_lobatto(n);
        }
    }
};

const ThicknessRules& thickness_rules() {
    static const ThicknessRules rules;
    return rules;
}

}  // namespace

std::span<const TrianglePoint> triangle_rule(int n_points) {
    if (n_points == 3) return k_tri3;
    if (n_points == 7) return k_tri7;
    throw std::invalid_argument("in-plane rule with " + std::to_string(n_points) +
                                " points does not exist (3 or 7)");
}

std::span<const ThicknessPoint> gauss_thickness_rule(int n_points) {
    if (n_points < 1 || n_points > k_max_thickness_points)
        throw std::invalid_argument("a Gauss rule through the thickness has 1 to 10 points, not " +
                                    std::to_string(n_points));
    if (n_points == 2) return k_gauss2;
    return thickness_rules().gauss[static_cast<std::size_t>(n_points - 1)];
}

std::span<const ThicknessPoint> lobatto_thickness_rule(int n_points) {
    if (n_points < 3 || n_points > k_max_thickness_points)
        throw std::invalid_argument(
            "a Lobatto rule through the thickness has 3 to 10 points, not " +
            std::to_string(n_points));
    if (n_points == 3) return k_lobatto3;
    if (n_points == 5) return k_lobatto5;
    return thickness_rules().lobatto[static_cast<std::size_t>(n_points - 1)];
}

std::span<const ThicknessPoint> thickness_rule(int n_points) {
    return n_points <= 2 ? gauss_thickness_rule(n_points) : lobatto_thickness_rule(n_points);
}

}  // namespace fpmshell

#include "fpmshell/model/model.hpp"

namespace fpmshell {

Real Curve::value(Real t) const {
    if (points.empty()) return 1.0;
    if (t <= points.front().first) return points.front().second;
    if (t >= points.back().first) return points.back().second;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const auto& [t1, f1] = points[i];
        if (t <= t1) {
            const auto& [t0, f0] = points[i - 1];
            if (t1 <= t0) return f1;
            return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
        }
    }
    return points.back().second;
}

Real Curve::integral(Real t) const {
    // Trapezoids between the points inside (0, t): exact, the curve being linear between them
    // and flat outside.
    std::vector<Real> knots{0.0};
    for (const auto& pt : points)
        if (pt.first > 0 && pt.first < t) knots.push_back(pt.first);
    knots.push_back(t);
    Real sum = 0;
    for (std::size_t i = 1; i < knots.size(); ++i)
        sum += 0.5 * (value(knots[i - 1]) + value(knots[i])) * (knots[i] - knots[i - 1]);
    return sum;
}

Real curve_factor(const std::vector<Curve>& curves, Index curve, Real t) {
    return curve < 0 ? 1.0 : curves[static_cast<std::size_t>(curve)].value(t);
}

Real curve_factor_integral(const std::vector<Curve>& curves, Index curve, Real t) {
    return curve < 0 ? t : curves[static_cast<std::size_t>(curve)].integral(t);
}

}  // namespace fpmshell

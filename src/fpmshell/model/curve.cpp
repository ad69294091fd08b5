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

}  // namespace fpmshell

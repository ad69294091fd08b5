// Tabulated flow curves (theory.md §7.2, eqs. 7.2-4 and 7.2-5): the flow stress as a
// piecewise-linear function of the plastic strain, one curve per strain rate (LS-DYNA's
// *MAT_024 with a load curve or a table of curves), evaluated on one point or on every lane of
// a pack (core/simd.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// sigma_f and sigma_f' at one plastic strain per lane of T.
template <class T>
struct FlowValue {
    T value, slope;
};

/// The curve through the points (strain[i], stress[i]), the plastic strains increasing from 0,
/// the stresses not decreasing (checked by the model reader); past the last point its last
/// segment goes on, as LS-DYNA extrapolates a *MAT_024 curve (eq. 7.2-4).
class PiecewiseLinearCurve {
public:
    PiecewiseLinearCurve(std::vector<Real> strain, std::vector<Real> stress)
        : strain_(std::move(strain)), stress_(std::move(stress)) {
        for (std::size_t i = 0; i + 1 < strain_.size(); ++i)
            slope_.push_back((stress_[i + 1] - stress_[i]) / (strain_[i + 1] - strain_[i]));
    }
    [[nodiscard]] const std::vector<Real>& strain() const { return strain_; }
    [[nodiscard]] const std::vector<Real>& stress() const { return stress_; }
    /// The segment that holds alpha: the last i < size - 1 with strain[i] <= alpha (0 below).
    [[nodiscard]] std::size_t segment(Real alpha) const {
        const auto above = std::upper_bound(strain_.begin() + 1, strain_.end() - 1, alpha);
        return static_cast<std::size_t>(above - strain_.begin()) - 1;
    }
    /// sigma_f(alpha) and its slope (the slope of the segment on the right at a point).
    [[nodiscard]] FlowValue<Real> at(Real alpha) const {
        const std::size_t i = segment(alpha);
        return {stress_[i] + slope_[i] * (alpha - strain_[i]), slope_[i]};
    }

private:
    std::vector<Real> strain_, stress_, slope_;  // slope_[i]: from point i to point i + 1
};

/// The position u = k + (rate - rates[k]) / (rates[k+1] - rates[k]) of `rate` among the
/// increasing `rates`, in [0, rates.size() - 1]: 0 below the first, the last index above the last.
[[nodiscard]] inline Real rate_position(const std::vector<Real>& rates, Real rate) {
    if (rates.size() < 2 || !(rate > rates.front())) return 0.0;
    if (!(rate < rates.back())) return static_cast<Real>(rates.size() - 1);
    const auto k = static_cast<std::size_t>(std::upper_bound(rates.begin(), rates.end(), rate) -
                                            rates.begin() - 1);
    return static_cast<Real>(k) + (rate - rates[k]) / (rates[k + 1] - rates[k]);
}

/// Flow curves at increasing strain rates (one curve: rate independent). A point's curve at
/// the rate `rate` is the linear interpolation between the two curves whose rates bracket it,
/// the first or the last curve outside their range (eq. 7.2-5). The position of a rate,
/// u = k + (rate - rate_k) / (rate_{k+1} - rate_k) in [0, curves - 1], is what a point carries
/// through its return (the rate is frozen during it, §7.4).
struct FlowTable {
    std::vector<PiecewiseLinearCurve> curves;
    std::vector<Real> rates;  ///< strictly increasing, one per curve

    [[nodiscard]] Real position(Real rate) const { return rate_position(rates, rate); }
    /// sigma_f and sigma_f' at the plastic strain alpha on the curve at position u.
    [[nodiscard]] FlowValue<Real> at(Real alpha, Real u) const {
        const FlowValue<Real> low = curves.front().at(alpha);
        if (!(u > 0.0)) return low;
        const std::size_t k =
            std::min(static_cast<std::size_t>(u), curves.size() - 2);  // u = last: k + 1 = last
        const Real w = u - static_cast<Real>(k);
        const FlowValue<Real> a = k == 0 ? low : curves[k].at(alpha), b = curves[k + 1].at(alpha);
        return {(1.0 - w) * a.value + w * b.value, (1.0 - w) * a.slope + w * b.slope};
    }
};

/// FlowTable::at on every lane of T, each lane with its own position (a binary search over the
/// points per lane and curve: the return mapping calls it once per evaluation).
template <class T>
[[nodiscard]] inline FlowValue<T> table_flow(const FlowTable& table, const T& alpha, const T& u) {
    if constexpr (std::is_same_v<T, Real>) {
        return table.at(alpha, u);
    } else {
        T value, slope;
        for (int l = 0; l < k_lanes; ++l) {
            const FlowValue<Real> v = table.at(lane(alpha, l), lane(u, l));
            set_lane(value, l, v.value);
            set_lane(slope, l, v.slope);
        }
        return {value, slope};
    }
}

/// The curve at one position per lane, as the return mapping's iteration evaluates it.
template <class T>
struct TableCurveAt {
    const FlowTable* table;
    T u;
    [[nodiscard]] FlowValue<T> operator()(const T& alpha) const {
        return table_flow(*table, alpha, u);
    }
};

/// rate_position on every lane of T.
template <class T>
[[nodiscard]] inline T rate_position(const std::vector<Real>& rates, const T& rate) {
    if constexpr (std::is_same_v<T, Real>) {
        return rate_position(rates, Real(rate));
    } else {
        T u;
        for (int l = 0; l < k_lanes; ++l) set_lane(u, l, rate_position(rates, lane(rate, l)));
        return u;
    }
}

}  // namespace fpmshell

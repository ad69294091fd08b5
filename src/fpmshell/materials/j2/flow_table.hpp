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
///
/// The curves are held on the union of their points (each exact there: piecewise linear, the
/// last segment extended), so that one search finds a plastic strain's segment on every curve.
class FlowTable {
public:
    FlowTable() = default;
    /// rates: strictly increasing, one per curve.
    FlowTable(const std::vector<PiecewiseLinearCurve>& curves, std::vector<Real> rates)
        : rates_(std::move(rates)), n_curves_(curves.size()) {
        for (const PiecewiseLinearCurve& c : curves)
            grid_.insert(grid_.end(), c.strain().begin(), c.strain().end());
        std::sort(grid_.begin(), grid_.end());
        grid_.erase(std::unique(grid_.begin(), grid_.end()), grid_.end());
        for (const PiecewiseLinearCurve& c : curves) {
            for (Real alpha : grid_) stress_.push_back(c.at(alpha).value);
            for (std::size_t i = 0; i + 1 < grid_.size(); ++i)
                slope_.push_back(c.at(grid_[i]).slope);
        }
    }
    [[nodiscard]] std::size_t size() const { return n_curves_; }
    [[nodiscard]] const std::vector<Real>& rates() const { return rates_; }
    [[nodiscard]] Real position(Real rate) const { return rate_position(rates_, rate); }
    /// sigma_f and sigma_f' at the plastic strain alpha on the curve at position u (eq. 7.2-5).
    [[nodiscard]] FlowValue<Real> at(Real alpha, Real u) const {
        const std::size_t n = grid_.size();
        const auto above = std::upper_bound(grid_.begin() + 1, grid_.end() - 1, alpha);
        const auto i = static_cast<std::size_t>(above - grid_.begin()) - 1;
        const Real d = alpha - grid_[i];
        if (!(u > 0.0)) return {stress_[i] + slope_[i] * d, slope_[i]};
        const std::size_t k =
            std::min(static_cast<std::size_t>(u), n_curves_ - 2);  // u = last: k + 1 = last
        const Real w = u - static_cast<Real>(k);
        const Real* s = stress_.data() + k * n;       // curve k at the points, then curve k + 1
        const Real* m = slope_.data() + k * (n - 1);  // its segments' slopes, then k + 1's
        const Real slope = (1.0 - w) * m[i] + w * m[n - 1 + i];
        return {(1.0 - w) * s[i] + w * s[n + i] + slope * d, slope};
    }

private:
    std::vector<Real> grid_;            // the points of every curve, increasing
    std::vector<Real> stress_, slope_;  // [curve][point] and [curve][segment]
    std::vector<Real> rates_;
    std::size_t n_curves_ = 0;
};

/// FlowTable::at on every lane of T, each lane with its own position (a binary search over the
/// points per lane: the return mapping calls it once per evaluation).
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

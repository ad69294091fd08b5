// Flow stress of the plastic materials and their strain-rate factor (theory.md §7.2, §7.4):
// sigma_f(alpha) is the uniaxial yield stress after the equivalent plastic strain alpha, at the
// reference rate; the rate factor R(rate) >= 1 multiplies it, or selects the curve of a table.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/simd_math.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/materials/j2/flow_table.hpp"

namespace fpmshell {

struct FlowStress {
    enum class Kind { Linear, JohnsonCook, Tabulated, PowerLaw };
    /// Johnson-Cook with n < 1: below this plastic strain the slope is taken at it.
    static constexpr Real k_slope_floor = 1e-6;
    Kind kind = Kind::Linear;
    Real yield_stress = 0;  ///< linear: sigma_y0
    Real hardening = 0;  ///< linear: plastic modulus H = E E_t / (E - E_t); 0 = perfectly plastic
    Real a = 0, b = 0, n = 1;  ///< Johnson-Cook A + B alpha^n
    /// power law (LS-DYNA *MAT_018): b (strain_offset + alpha)^n, the offset the elastic strain
    /// at yield (theory.md eq. 7.2-6)
    Real strain_offset = 0;
    /// Tabulated (theory.md §7.2, eqs. 7.2-4, 7.2-5): sigma_f(alpha) is the first (lowest-rate)
    /// curve of the table; a rate-dependent table's other curves come in through the point's
    /// position among the rates (RateFactor::Kind::Table).
    FlowTable table;

    /// A tabulated curve (two points at least, checked by the model reader).
    [[nodiscard]] static FlowStress tabulated(std::vector<PiecewiseLinearCurve> curves,
                                              std::vector<Real> rates = {0.0}) {
        FlowStress f;
        f.kind = Kind::Tabulated;
        f.table = FlowTable(curves, std::move(rates));
        return f;
    }
    [[nodiscard]] static FlowStress tabulated(std::vector<Real> strain, std::vector<Real> stress) {
        return tabulated({PiecewiseLinearCurve(std::move(strain), std::move(stress))});
    }

    [[nodiscard]] Real value(Real alpha) const {
        if (kind == Kind::Linear) return yield_stress + hardening * alpha;
        if (kind == Kind::Tabulated) return table.at(alpha, 0.0).value;
        if (kind == Kind::PowerLaw) return b * std::pow(strain_offset + alpha, n);
        return a + (alpha > 0 ? b * std::pow(alpha, n) : 0.0);
    }
    /// d sigma_f / d alpha; for Johnson-Cook with n < 1 the slope is infinite at alpha = 0:
    /// it is taken at a small plastic strain instead (the return mapping iterates on the flow
    /// stress there and does not rely on this slope, theory.md §7.3a).
    [[nodiscard]] Real slope(Real alpha) const {
        if (kind == Kind::Linear) return hardening;
        if (kind == Kind::Tabulated) return table.at(alpha, 0.0).slope;
        if (kind == Kind::PowerLaw) return b * n * std::pow(strain_offset + alpha, n - 1.0);
        const Real at = std::max(alpha, k_slope_floor);
        return b * n * std::pow(at, n - 1.0);
    }
    struct ValueSlope {
        Real value, slope;
    };
    /// value and slope together, with one power for Johnson-Cook (the return mapping's Newton
    /// loop needs both at every iterate). Equal to value() and slope() to rounding.
    [[nodiscard]] ValueSlope value_and_slope(Real alpha) const {
        if (kind == Kind::Linear) return {yield_stress + hardening * alpha, hardening};
        if (kind == Kind::Tabulated) {
            const FlowValue<Real> v = table.at(alpha, 0.0);
            return {v.value, v.slope};
        }
        if (kind == Kind::PowerLaw) {
            const Real e = strain_offset + alpha, p = std::pow(e, n - 1.0);
            return {b * e * p, b * n * p};
        }
        if (!(alpha >= k_slope_floor)) return {value(alpha), slope(alpha)};
        const Real p = std::pow(alpha, n - 1.0);  // alpha^n = alpha alpha^(n-1)
        return {a + b * alpha * p, b * n * p};
    }
};

/// The rate dependence of a plastic material: a factor R(rate) on the yield radius
/// (Cowper-Symonds, Johnson-Cook, a curve of the factor against the rate), or, for a table of
/// flow curves (Kind::Table), the position of the rate among the table's rates, which selects
/// the curve (FlowTable::position).
struct RateFactor {
    enum class Kind { None, CowperSymonds, JohnsonCook, Table, Curve };
    Kind kind = Kind::None;
    Real d = 0, q = 1;               ///< Cowper-Symonds: 1 + (rate / D)^(1/q)
    Real c = 0, reference_rate = 1;  ///< Johnson-Cook: 1 + C ln(max(rate / rate_0, 1))
    std::vector<Real> table_rates;   ///< Table: the rates of its curves (FlowTable::rates())
    /// Curve (LS-DYNA's *MAT_024 LCSR; theory.md eq. 7.4-3): the factor piecewise linear in
    /// the rate through its points, its end segments going on past them (as LS-DYNA extends a
    /// curve); the points' rates increasing, the factors > 0 and not decreasing
    PiecewiseLinearCurve scaling{{}, {}};

    [[nodiscard]] bool active() const { return kind != Kind::None; }
    [[nodiscard]] bool selects_curve() const { return kind == Kind::Table; }
    /// R(rate) (the curve's position for a table) on every lane of T (core/simd.hpp), with the
    /// logarithm and power of core/simd_math.hpp: the element blocks take a pack of rates at
    /// once, and a point computed alone gets the same factor as its lane would.
    template <class T>
    [[nodiscard]] T value(const T& rate) const {
        switch (kind) {
            case Kind::Table:
                return rate_position(table_rates, rate);
            case Kind::CowperSymonds: {
                const MaskOf<T> moving = rate > 0.0;
                const T ratio = select(moving, max(rate * (1.0 / d), T(1e-300)), T(1.0));
                return select(moving, 1.0 + vector_pow(ratio, T(1.0 / q)), T(1.0));
            }
            case Kind::JohnsonCook: {  // below the reference rate the factor is 1
                const MaskOf<T> fast = rate > reference_rate;
                const T ratio = select(fast, rate * (1.0 / reference_rate), T(1.0));
                return select(fast, 1.0 + c * vector_log(ratio), T(1.0));
            }
            case Kind::Curve: {  // lane by lane: a lane equals its scalar
                if constexpr (std::is_same_v<T, Real>) {
                    return scaling.at(rate).value;
                } else {
                    T factor(1.0);
                    for (int l = 0; l < lanes_of<T>; ++l)
                        set_lane(factor, l, scaling.at(lane(rate, l)).value);
                    return factor;
                }
            }
            default:
                return T(1.0);
        }
    }
};

}  // namespace fpmshell

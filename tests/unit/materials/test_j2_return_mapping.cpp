// The return mapping of theory.md §7.3 on k_lanes points at once
// (materials/j2/j2_return_mapping.hpp, T = RealPack) against the same points one by one (T = Real,
// what J2Plastic::update runs and test_j2_plastic.cpp checks against closed forms and an
// independent 3-D algorithm):
// - every lane equals its scalar return, for lanes that stay elastic, yield for the first time,
//   yield again, need many Newton steps or few, with a linear, a Johnson-Cook or a tabulated
//   flow curve and a rate factor of their own;
// - a lane outside the mask returns its trial state and no plastic work, even outside the
//   yield surface;
// - J2Plastic::update is the scalar return with the filtered rate's factor.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <utility>

#include "fpmshell/materials/j2/j2_plastic.hpp"
#include "fpmshell/materials/j2/j2_return_mapping.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_e = 200e9, k_nu = 0.3, k_sy = 250e6;

J2Plastic bilinear(Real hardening, Real beta) {
    FlowStress f;
    f.yield_stress = k_sy;
    f.hardening = hardening;
    return J2Plastic(k_e, k_nu, f, RateFactor{}, beta);
}

J2Plastic johnson_cook(Real beta, Real n = 0.4) {  // the tube's steel (benchmarks.md 5.3), n < 1
    FlowStress f;
    f.kind = FlowStress::Kind::JohnsonCook;
    f.a = k_sy;
    f.b = 500e6;
    f.n = n;
    RateFactor rate;
    rate.kind = RateFactor::Kind::JohnsonCook;
    rate.c = 0.02;
    rate.reference_rate = 1.0;
    return J2Plastic(k_e, k_nu, f, rate, beta);
}

/// A tabulated curve whose points lie within the random states' plastic strains (up to 0.05)
/// and the increments' reach: lanes cross points during a return, some end on its flat part or
/// past its last point.
J2Plastic tabulated(Real beta) {
    const FlowStress f =
        FlowStress::tabulated({0.0, 0.004, 0.015, 0.03, 0.045, 0.07},
                              {k_sy, 1.2 * k_sy, 1.4 * k_sy, 1.5 * k_sy, 1.5 * k_sy, 1.55 * k_sy});
    RateFactor rate;
    rate.kind = RateFactor::Kind::CowperSymonds;
    rate.d = 40.4;
    rate.q = 5.0;
    return J2Plastic(k_e, k_nu, f, rate, beta);
}

/// A power law (LS-DYNA *MAT_018, eq. 7.2-6) of exponent n from the yield stress k_sy, with a
/// Cowper-Symonds factor.
J2Plastic power_law(Real beta, Real n) {
    FlowStress f;
    f.kind = FlowStress::Kind::PowerLaw;
    f.b = 900e6;
    f.n = n;
    f.strain_offset = std::pow(k_sy / f.b, 1.0 / n);
    RateFactor rate;
    rate.kind = RateFactor::Kind::CowperSymonds;
    rate.d = 40.4;
    rate.q = 5.0;
    return J2Plastic(k_e, k_nu, f, rate, beta);
}

/// Three tabulated curves at 0, 10 and 1000 /s, the higher ones on or above the lower and with
/// points of their own (theory.md eq. 7.2-5).
J2Plastic rate_table() {
    const std::vector<Real> rates{0.0, 10.0, 1000.0};
    const FlowStress f = FlowStress::tabulated(
        {PiecewiseLinearCurve({0.0, 0.004, 0.015, 0.07},
                              {k_sy, 1.2 * k_sy, 1.4 * k_sy, 1.5 * k_sy}),
         PiecewiseLinearCurve({0.0, 0.01, 0.03}, {1.1 * k_sy, 1.35 * k_sy, 1.6 * k_sy}),
         PiecewiseLinearCurve({0.0, 0.002, 0.02, 0.05},
                              {1.3 * k_sy, 1.4 * k_sy, 1.7 * k_sy, 1.8 * k_sy})},
        rates);
    RateFactor rate;
    rate.kind = RateFactor::Kind::Table;
    rate.table_rates = rates;
    return J2Plastic(k_e, k_nu, f, rate, 1.0);
}

/// A random history of one point: on or inside its yield surface, some never yielded.
J2PointState<Real> random_state(std::mt19937& rng, const J2ReturnConstants& c) {
    std::uniform_real_distribution<Real> u(-1.0, 1.0), v(0.0, 1.0);
    J2PointState<Real> s{};
    const bool hardened = v(rng) < 0.6;
    s.plastic_strain = hardened ? 0.05 * v(rng) : 0.0;
    if (hardened) {
        const FlowStress::ValueSlope f = c.flow.value_and_slope(s.plastic_strain);
        s.flow_radius = c.flow_radius0 + c.beta * (f.value - c.flow_radius0);
        s.flow_slope = f.slope;
    } else {  // what a point that never yielded holds (J2Plastic::update's elastic branch)
        s.flow_radius = c.flow_radius0;
        s.flow_slope = -1.0;
    }
    for (std::size_t k = 0; k < 3; ++k) {
        s.back_stress[k] = hardened ? 0.2 * k_sy * u(rng) : 0.0;
        s.stress[k] = s.back_stress[k] + 0.45 * k_sy * u(rng);  // |xi| below the yield radius
    }
    return s;
}

/// A strain increment: most in the elastic range (|d eps| ~ 1e-4), some far past yield
/// (|d eps| ~ 2e-2, many Newton steps and the bisection fallback).
std::array<Real, 3> random_increment(std::mt19937& rng) {
    std::uniform_real_distribution<Real> u(-1.0, 1.0), v(0.0, 1.0);
    const Real size = v(rng) < 0.2 ? 2e-2 : (v(rng) < 0.5 ? 3e-3 : 1e-4);
    return {size * u(rng), size * u(rng), size * u(rng)};
}

/// The same comparison for every lane of `trials` random packs; returns how many lanes yielded.
/// rate_factors: each lane's r in [1, 1.3] (a rate factor R), or with rate_positions its
/// position in a rate table, in [0, rate_positions].
int check_lanes_against_scalar(const J2ReturnConstants& c, bool rate_factors, int trials,
                               Real rate_positions = 0.0) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> v(0.0, 1.0);
    int n_yielded = 0;
    for (int trial = 0; trial < trials; ++trial) {
        std::array<J2PointState<Real>, k_lanes> old;
        std::array<std::array<Real, 3>, k_lanes> d_eps;
        std::array<Real, k_lanes> r;
        RealPack::mask_type lanes(true);
        for (std::size_t l = 0; l < k_lanes; ++l) {
            old[l] = random_state(rng, c);
            d_eps[l] = random_increment(rng);
            r[l] = rate_positions > 0 ? rate_positions * v(rng)
                   : rate_factors     ? 1.0 + 0.3 * v(rng)
                                      : 1.0;
        }
        auto pack = [&](auto&& f) {
            return RealPack([&](auto l) { return f(static_cast<std::size_t>(l)); });
        };
        J2PointState<RealPack> old_pack;
        std::array<RealPack, 3> d_eps_pack;
        for (std::size_t k = 0; k < 3; ++k) {
            old_pack.stress[k] = pack([&](std::size_t l) { return old[l].stress[k]; });
            old_pack.back_stress[k] = pack([&](std::size_t l) { return old[l].back_stress[k]; });
            d_eps_pack[k] = pack([&](std::size_t l) { return d_eps[l][k]; });
        }
        old_pack.plastic_strain = pack([&](std::size_t l) { return old[l].plastic_strain; });
        old_pack.flow_radius = pack([&](std::size_t l) { return old[l].flow_radius; });
        old_pack.flow_slope = pack([&](std::size_t l) { return old[l].flow_slope; });
        const J2Return<RealPack> out = j2_return_mapping(
            c, old_pack, d_eps_pack, pack([&](std::size_t l) { return r[l]; }), lanes);
        for (int l = 0; l < k_lanes; ++l) {
            SCOPED_TRACE(::testing::Message() << "trial " << trial << " lane " << l);
            const std::size_t ul = static_cast<std::size_t>(l);
            const J2Return<Real> ref = j2_return_mapping(c, old[ul], d_eps[ul], r[ul], true);
            EXPECT_EQ(lane(out.yielded, l), ref.yielded);
            n_yielded += ref.yielded ? 1 : 0;
            // The lane and the scalar run the same operations; the compiler may contract a*b+c
            // into an FMA in one and not the other, and that rounding can move the converged
            // Newton iterate anywhere within the convergence tolerance |F| < 1e-10 kappa^2 / 3:
            // relative 1e-10 in the stresses, so 1e-9 of the yield stress bounds it.
            const Real tol = 1e-9 * k_sy;
            for (std::size_t k = 0; k < 3; ++k) {
                EXPECT_NEAR(lane(out.state.stress[k], l), ref.state.stress[k], tol);
                EXPECT_NEAR(lane(out.state.back_stress[k], l), ref.state.back_stress[k], tol);
            }
            // alpha, kappa and the work follow from the stresses: the same relative 1e-9
            EXPECT_NEAR(lane(out.state.plastic_strain, l), ref.state.plastic_strain,
                        1e-9 * (ref.state.plastic_strain + 1e-3));
            EXPECT_NEAR(lane(out.state.flow_radius, l), ref.state.flow_radius, tol);
            EXPECT_NEAR(lane(out.state.flow_slope, l), ref.state.flow_slope,
                        1e-9 * std::abs(ref.state.flow_slope) + 1e-6);
            EXPECT_NEAR(lane(out.plastic_work, l), ref.plastic_work,
                        1e-9 * std::abs(ref.plastic_work) + 1e-3);
        }
    }
    return n_yielded;
}

}  // namespace

TEST(J2ReturnMapping, EveryLaneEqualsItsScalarReturnLinearMixedHardening) {
    const int yielded =
        check_lanes_against_scalar(bilinear(2e9, 0.5).return_constants(), false, 200);
    EXPECT_GT(yielded, 200 * k_lanes / 4);  // the random states do exercise the return
    EXPECT_LT(yielded, 200 * k_lanes);      // and the elastic lanes next to yielding ones
}

TEST(J2ReturnMapping, EveryLaneEqualsItsScalarReturnPerfectlyPlastic) {
    check_lanes_against_scalar(bilinear(0.0, 1.0).return_constants(), false, 100);
}

TEST(J2ReturnMapping, EveryLaneEqualsItsScalarReturnJohnsonCookWithRateFactors) {
    check_lanes_against_scalar(johnson_cook(0.5).return_constants(), true, 200);
    check_lanes_against_scalar(johnson_cook(0.0).return_constants(), true, 100);  // kinematic
    // the exponents at the ends of the range: the flow-stress iteration (n <= 1) and the
    // dgamma iteration with the curve on packs (n > 1)
    for (Real n : {0.1, 1.0, 1.5})
        check_lanes_against_scalar(johnson_cook(1.0, n).return_constants(), true, 100);
}

TEST(J2ReturnMapping, EveryLaneEqualsItsScalarReturnTabulatedWithRateFactors) {
    for (Real beta : {1.0, 0.3}) {
        const int yielded =
            check_lanes_against_scalar(tabulated(beta).return_constants(), true, 400);
        EXPECT_GT(yielded, 400) << "beta " << beta;  // enough yielding lanes to mean something
    }
}

TEST(J2ReturnMapping, EveryLaneEqualsItsScalarReturnPowerLawWithRateFactors) {
    for (const auto& [beta, n] : {std::pair{1.0, 0.25}, std::pair{0.5, 0.5}, std::pair{1.0, 1.3}}) {
        const int yielded =
            check_lanes_against_scalar(power_law(beta, n).return_constants(), true, 200);
        EXPECT_GT(yielded, 200) << "beta " << beta << ", n " << n;
    }
}

TEST(J2ReturnMapping, EveryLaneEqualsItsScalarReturnOnTheCurveOfItsRate) {
    const int yielded =
        check_lanes_against_scalar(rate_table().return_constants(), false, 400, 2.0);
    EXPECT_GT(yielded, 400);
}

TEST(J2ReturnMapping, LanesOutsideTheMaskKeepTheirTrialState) {
    const J2Plastic mat = bilinear(2e9, 1.0);
    const J2ReturnConstants& c = mat.return_constants();
    J2PointState<RealPack> old{};
    old.flow_radius = c.flow_radius0;
    old.flow_slope = -1.0;
    // every lane strained far past yield in x
    const std::array<RealPack, 3> d_eps{RealPack(0.01), RealPack(0.0), RealPack(0.0)};
    RealPack::mask_type lanes(false);
    for (int l = 0; l < k_lanes; l += 2) lanes[static_cast<std::size_t>(l)] = true;
    const J2Return<RealPack> out = j2_return_mapping(c, old, d_eps, RealPack(1.0), lanes);
    for (int l = 0; l < k_lanes; ++l) {
        SCOPED_TRACE(::testing::Message() << "lane " << l);
        if (l % 2 == 0) {
            EXPECT_TRUE(lane(out.yielded, l));
            EXPECT_GT(lane(out.plastic_work, l), 0.0);
            EXPECT_LT(lane(out.state.stress[0], l), 0.5 * c.c11 * 0.01);  // returned
        } else {
            EXPECT_FALSE(lane(out.yielded, l));
            EXPECT_EQ(lane(out.plastic_work, l), 0.0);
            EXPECT_EQ(lane(out.state.stress[0], l), c.c11 * 0.01);  // trial
            EXPECT_EQ(lane(out.state.plastic_strain, l), 0.0);
        }
    }
}

TEST(J2ReturnMapping, UpdateIsTheScalarReturnAtTheFilteredRate) {
    const J2Plastic mat = johnson_cook(0.5);
    MaterialPoint p;
    p.stress = Voigt3(200e6, -30e6, 40e6);
    p.back_stress = Voigt3(10e6, -5e6, 2e6);
    p.plastic_strain = 0.02;
    p.flow_radius = mat.yield_radius(0.02, 1.0);
    p.flow_slope = mat.return_constants().flow.slope(0.02);
    p.strain_rate = 300.0;
    p.plastic_work = 1e6;
    const Voigt3 d_eps(2e-3, -1e-3, 5e-4);
    const Real dt = 1e-6;
    MaterialPoint q;
    mat.update(p, d_eps, dt, q);
    const Real rate =
        J2Plastic::k_rate_filter * effective_strain_rate<Real>({d_eps(0), d_eps(1), d_eps(2)}, dt) +
        (1 - J2Plastic::k_rate_filter) * 300.0;
    const J2Return<Real> ref = j2_return_mapping(
        mat.return_constants(),
        J2PointState<Real>{
            {200e6, -30e6, 40e6}, {10e6, -5e6, 2e6}, 0.02, p.flow_radius, p.flow_slope},
        {2e-3, -1e-3, 5e-4}, mat.rate_factor().value(q.strain_rate), true);
    ASSERT_TRUE(ref.yielded);
    EXPECT_DOUBLE_EQ(q.strain_rate, rate);  // the filter of §7.4 option a (to rounding)
    // update and the return above may round an FMA differently (other translation units):
    // within the Newton tolerance, as in the lane comparisons above
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(q.stress(k), ref.state.stress[static_cast<std::size_t>(k)], 1e-9 * k_sy);
    EXPECT_NEAR(q.plastic_strain, ref.state.plastic_strain, 1e-9 * ref.state.plastic_strain);
    EXPECT_NEAR(q.plastic_work, 1e6 + ref.plastic_work, 1e-9 * ref.plastic_work);
    EXPECT_GT(q.plastic_strain, 0.02);
}

// Step 3 of the return mapping (materials/j2/j2_consistency.hpp, theory.md §7.3a) against a
// reference that shares none of its code: the consistency condition F(dgamma) = 0 of §7.3 in
// its squared form, with libm's pow for the flow curve, solved by bisection to the last bit,
// then step 4 written out again. Random states include points that never yielded (alpha_n = 0,
// where a Johnson-Cook slope with n < 1 is infinite), Johnson-Cook exponents 0.1 ... 1 and
// above, isotropic, mixed and kinematic hardening, and rate factors R > 1. Also: how many
// evaluations of the residual the Newton iterations take.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "fpmshell/materials/j2/j2_plastic.hpp"
#include "fpmshell/materials/j2/j2_return_mapping.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_e = 200e9, k_nu = 0.3;

J2Plastic johnson_cook(Real n, Real beta) {  // the crushed half-cylinder, exponent n
    FlowStress f;
    f.kind = FlowStress::Kind::JohnsonCook;
    f.a = 180e6;
    f.b = 450e6;
    f.n = n;
    return J2Plastic(k_e, k_nu, f, RateFactor{}, beta);
}

J2Plastic bilinear(Real hardening, Real beta) {
    FlowStress f;
    f.yield_stress = 250e6;
    f.hardening = hardening;
    return J2Plastic(k_e, k_nu, f, RateFactor{}, beta);
}

struct Reference {
    bool yielded = false;
    std::array<Real, 3> stress{};
    Real plastic_strain = 0;
};

/// §7.3 with the root of F(dgamma) = f_bar^2 / 2 - kappa(alpha(dgamma))^2 / 3 by bisection.
Reference reference_return(const J2Plastic& mat, const J2PointState<Real>& old,
                           const std::array<Real, 3>& d_eps, Real r) {
    const J2ReturnConstants& c = mat.return_constants();
    const FlowStress& fl = c.flow;
    const Real f0 = fl.value(0), beta = c.beta, alpha_n = old.plastic_strain;
    auto kappa = [&](Real alpha) { return r * (f0 + beta * (fl.value(alpha) - f0)); };
    const Real sx = old.stress[0] + c.c11 * d_eps[0] + c.c12 * d_eps[1];
    const Real sy = old.stress[1] + c.c12 * d_eps[0] + c.c11 * d_eps[1];
    const Real sxy = old.stress[2] + c.c33 * d_eps[2];
    const Real x1 = sx - old.back_stress[0], x2 = sy - old.back_stress[1],
               x12 = sxy - old.back_stress[2];
    const Real a1_sq = (x1 + x2) * (x1 + x2) / 6, a2_sq = (x2 - x1) * (x2 - x1) / 2 + 2 * x12 * x12;
    const Real k_n = kappa(alpha_n);
    Reference out;
    out.stress = {sx, sy, sxy};
    out.plastic_strain = alpha_n;
    if (0.5 * (a1_sq + a2_sq) - k_n * k_n / 3 <= c.tolerance * k_n * k_n / 3) return out;
    out.yielded = true;
    const Real h_k = (1 - beta) * r * fl.slope(alpha_n);
    const Real a1 = c.bulk_term + 2.0 / 3 * h_k, a2 = c.two_g + 2.0 / 3 * h_k;
    auto fbar = [&](Real dg) {
        return std::sqrt(a1_sq / ((1 + a1 * dg) * (1 + a1 * dg)) +
                         a2_sq / ((1 + a2 * dg) * (1 + a2 * dg)));
    };
    auto alpha = [&](Real dg) { return alpha_n + std::sqrt(2.0 / 3) * dg * fbar(dg); };
    auto f = [&](Real dg) {
        const Real k = kappa(alpha(dg));
        return 0.5 * fbar(dg) * fbar(dg) - k * k / 3;
    };
    Real lo = 0, hi = 1e-12;
    while (f(hi) > 0) hi *= 2;
    for (int i = 0; i < 200 && hi > std::nextafter(lo, hi); ++i) {
        const Real mid = 0.5 * (lo + hi);
        (f(mid) > 0 ? lo : hi) = mid;
    }
    const Real dg = 0.5 * (lo + hi);
    const Real s = (x1 + x2) / (1 + a1 * dg), d = (x2 - x1) / (1 + a2 * dg);
    const std::array<Real, 3> xi{0.5 * (s - d), 0.5 * (s + d), x12 / (1 + a2 * dg)};
    for (std::size_t k = 0; k < 3; ++k)
        out.stress[k] = old.back_stress[k] + (1 + 2.0 / 3 * h_k * dg) * xi[k];
    const Real xs = xi[0] + xi[1], xd = xi[1] - xi[0];
    out.plastic_strain = alpha_n + std::sqrt(2.0 / 3) * dg *
                                       std::sqrt(xs * xs / 6 + xd * xd / 2 + 2 * xi[2] * xi[2]);
    return out;
}

/// A point on its yield surface (or inside, for some), hardened or never yielded.
J2PointState<Real> random_state(std::mt19937& rng, const J2ReturnConstants& c, bool virgin,
                                Real r) {
    std::uniform_real_distribution<Real> u(-1.0, 1.0), v(0.0, 1.0);
    J2PointState<Real> s{};
    s.plastic_strain = virgin ? 0.0 : std::pow(10.0, -6 + 5.5 * v(rng));  // 1e-6 ... 0.3
    const Real f0 = c.flow_radius0;
    if (virgin) {
        s.flow_radius = f0;
        s.flow_slope = -1.0;
    } else {
        const FlowStress::ValueSlope f = c.flow.value_and_slope(s.plastic_strain);
        s.flow_radius = f0 + c.beta * (f.value - f0);
        s.flow_slope = f.slope;
    }
    const std::array<Real, 3> dir{u(rng), u(rng), u(rng)};
    const Real ds = dir[0] + dir[1], dd = dir[1] - dir[0];
    const Real p2 = ds * ds / 6 + dd * dd / 2 + 2 * dir[2] * dir[2];
    const Real on_surface = std::sqrt(2.0 / 3) * r * s.flow_radius / std::sqrt(p2);
    const Real scale = on_surface * (v(rng) < 0.8 ? 1.0 : v(rng));
    for (std::size_t k = 0; k < 3; ++k) {
        s.back_stress[k] = virgin ? 0.0 : 0.2 * f0 * (1 - c.beta) * u(rng);
        s.stress[k] = s.back_stress[k] + scale * dir[k];
    }
    return s;
}

/// Increments from 1e-6 (a trial overshoot of a fraction of a per cent) to 3e-2 (tens of yield
/// strains: far past yield in one step).
std::array<Real, 3> random_increment(std::mt19937& rng) {
    std::uniform_real_distribution<Real> u(-1.0, 1.0), v(0.0, 1.0);
    const Real size = 3.0 * std::pow(10.0, -6 + 4.5 * v(rng));
    return {size * u(rng), size * u(rng), size * u(rng)};
}

struct Agreement {
    int yielded = 0, most_evaluations = 0;
};

Agreement check_against_reference(const J2Plastic& mat, bool virgin, bool rate, int trials,
                                  unsigned seed) {
    const J2ReturnConstants& c = mat.return_constants();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> v(0.0, 1.0);
    Agreement a;
    for (int trial = 0; trial < trials; ++trial) {
        const Real r = rate ? 1.0 + 0.3 * v(rng) : 1.0;
        const J2PointState<Real> old = random_state(rng, c, virgin, r);
        const std::array<Real, 3> d_eps = random_increment(rng);
        const J2Return<Real> got = j2_return_mapping(c, old, d_eps, r, true);
        const Reference ref = reference_return(mat, old, d_eps, r);
        SCOPED_TRACE(::testing::Message()
                     << "trial " << trial << " alpha_n " << old.plastic_strain << " d_eps "
                     << d_eps[0] << " " << d_eps[1] << " " << d_eps[2] << " R " << r);
        EXPECT_EQ(got.yielded, ref.yielded);
        if (!ref.yielded || !got.yielded) continue;
        ++a.yielded;
        a.most_evaluations = std::max(a.most_evaluations, got.evaluations);
        // Tolerance: the iteration stops at |F| < 1e-10 kappa_n^2 / 3; F = (s_eq^2 - kappa^2) / 3
        // puts the equivalent stress within 1.5e-10 kappa / 2 of the yield radius, and the
        // stresses move by no more than that scale: 1e-9 kappa (x 10 margin) bounds the
        // difference from the exact root.
        const Real kappa =
            r * (c.flow_radius0 + c.beta * (c.flow.value(ref.plastic_strain) - c.flow_radius0));
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_NEAR(got.state.stress[k], ref.stress[k], 1e-9 * kappa) << "component " << k;
        // alpha_{n+1} - alpha_n is proportional to dgamma, known to the same relative 1e-9
        // where the increment is large, and to 1e-9 kappa / E in absolute terms where small
        EXPECT_NEAR(got.state.plastic_strain, ref.plastic_strain,
                    1e-9 * (ref.plastic_strain - old.plastic_strain) + 1e-9 * kappa / k_e);
    }
    return a;
}

}  // namespace

TEST(J2Consistency, JohnsonCookAgreesWithTheReferenceFromAlphaZero) {
    for (Real n : {0.1, 0.25, 0.5, 0.75, 1.0}) {
        SCOPED_TRACE(::testing::Message() << "n " << n);
        for (Real beta : {1.0, 0.5}) {
            const Agreement a = check_against_reference(johnson_cook(n, beta), true, true, 400, 3);
            EXPECT_GT(a.yielded, 100);
            // from alpha_n = 0, where sigma_f' is infinite for n < 1: a few evaluations
            EXPECT_LE(a.most_evaluations, 8) << "beta " << beta;
        }
    }
}

TEST(J2Consistency, JohnsonCookAgreesWithTheReferenceWhenHardened) {
    for (Real n : {0.1, 0.25, 0.5, 0.75, 1.0}) {
        SCOPED_TRACE(::testing::Message() << "n " << n);
        for (Real beta : {1.0, 0.5}) {
            const Agreement a = check_against_reference(johnson_cook(n, beta), false, true, 400, 5);
            EXPECT_GT(a.yielded, 100);
            EXPECT_LE(a.most_evaluations, 8) << "beta " << beta;
        }
    }
}

TEST(J2Consistency, JohnsonCookKinematicAndConvexCurvesAgreeWithTheReference) {
    // beta = 0 and n > 1 iterate on dgamma with the curve on packs
    for (bool virgin : {true, false}) {
        check_against_reference(johnson_cook(0.5, 0.0), virgin, true, 300, 7);
        check_against_reference(johnson_cook(1.5, 1.0), virgin, true, 300, 9);
    }
}

TEST(J2Consistency, BilinearAgreesWithTheReference) {
    for (bool virgin : {true, false}) {
        for (Real beta : {1.0, 0.5, 0.0}) {
            const Agreement a =
                check_against_reference(bilinear(1e10, beta), virgin, true, 300, 11);
            EXPECT_LE(a.most_evaluations, 6);
            check_against_reference(bilinear(0.0, beta), virgin, false, 200, 13);
        }
    }
}

TEST(J2Consistency, FirstYieldOfJohnsonCookTakesAFewEvaluations) {
    // A point that never yielded, strained past yield by an overshoot of 0.1 % to 100 % of the
    // yield stress: sigma_f' = B n alpha^(n-1) is infinite where the iteration starts.
    for (Real n : {0.1, 0.3, 0.5, 0.8}) {
        const J2Plastic mat = johnson_cook(n, 1.0);
        const J2ReturnConstants& c = mat.return_constants();
        for (Real overshoot : {1e-3, 1e-2, 1e-1, 1.0}) {
            J2PointState<Real> old{};
            old.flow_radius = c.flow_radius0;
            old.flow_slope = -1.0;
            // uniaxial stress at the yield stress, then a uniaxial stress increment
            old.stress = {c.flow_radius0, 0.0, 0.0};
            const Real de = overshoot * c.flow_radius0 / k_e;
            const std::array<Real, 3> d_eps{de, -k_nu * de, 0.0};
            const J2Return<Real> got = j2_return_mapping(c, old, d_eps, 1.0, true);
            ASSERT_TRUE(got.yielded);
            EXPECT_LE(got.evaluations, 7) << "n " << n << " overshoot " << overshoot;
            const Reference ref = reference_return(mat, old, d_eps, 1.0);
            EXPECT_NEAR(got.state.stress[0], ref.stress[0], 1e-9 * c.flow_radius0);
        }
    }
}

TEST(J2Consistency, HardenedJohnsonCookStepTakesTwoEvaluations) {
    // A crash step: a hardened point on its yield surface, strained on by a trial overshoot of
    // 1 % to 10 % of its yield stress. Halley's steps in y (eq. 7.3a-7) converge at the second
    // evaluation; Newton's steps (d2phi = 0) take a third on 10 of these 36 cases.
    for (Real n : {0.1, 0.36, 0.5, 0.8}) {
        const J2Plastic mat = johnson_cook(n, 1.0);
        const J2ReturnConstants& c = mat.return_constants();
        for (Real alpha_n : {0.01, 0.1, 1.0}) {
            for (Real overshoot : {1e-2, 3e-2, 1e-1}) {
                J2PointState<Real> old{};
                const FlowStress::ValueSlope f = c.flow.value_and_slope(alpha_n);
                old.plastic_strain = alpha_n;
                old.flow_radius = f.value;
                old.flow_slope = f.slope;
                old.stress = {f.value, 0.0, 0.0};
                const Real de = overshoot * f.value / k_e;
                const std::array<Real, 3> d_eps{de, -k_nu * de, 0.0};
                const J2Return<Real> got = j2_return_mapping(c, old, d_eps, 1.0, true);
                ASSERT_TRUE(got.yielded);
                EXPECT_LE(got.evaluations, 2)
                    << "n " << n << " alpha_n " << alpha_n << " overshoot " << overshoot;
                const Reference ref = reference_return(mat, old, d_eps, 1.0);
                EXPECT_NEAR(got.state.stress[0], ref.stress[0], 1e-9 * f.value);
            }
        }
    }
}

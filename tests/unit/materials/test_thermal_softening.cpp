// Johnson-Cook's thermal softening with adiabatic heating (theory.md eq. 7.4-2) on an
// equibiaxial stretch, against the closed form and an independent integration:
// - in equibiaxial stress sigma_eq = sigma and dW_p = sigma d alpha, so the plastic work obeys
//   dW/d alpha = sigma_f(alpha) Theta(W), Theta = 1 - (h W)^m, h = chi / (rho c_p (T_m - T_r));
//   for m = 1 it integrates to W = (1 - exp(-h F(alpha))) / h, F = A alpha + B alpha^(n+1)/(n+1);
//   for m = 1/2 by fourth-order Runge-Kutta in fine steps;
// - the material's stress is sigma_f(alpha) Theta(W) at its own alpha, W (the scalar update),
//   and a plate stretched so in the solver (its elements in SIMD blocks) follows the same curve;
// - without the factor the stress would be 25 % to 60 % higher: the test tells the two apart.
#include <gtest/gtest.h>

#include <cmath>

#include "../one_section_model.hpp"
#include "fpmshell/materials/johnson_cook/johnson_cook_law.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

// A Johnson-Cook steel whose specific heat is lowered (c_p = 60 instead of ~450) so that the
// stretch heats it to T* ~ 0.5: the factor then changes the stress by tens of per cent.
constexpr Real k_a = 3.5e8, k_b = 2.75e8, k_n = 0.36;

Material hot_steel(Real m_exponent) {
    Material mat{"steel", "elastic", 7850, 2.0e11, 0.3};
    make_johnson_cook(mat, k_a, k_b, k_n).thermal =
        adiabatic_softening(m_exponent, 1793, 293, 60, 0.9, mat.density);
    return mat;
}

/// The exponent m of a hot_steel.
Real exponent(const Material& mat) { return j2_parameters(mat)->thermal.m; }

Real heating(const Material& mat) {
    return 0.9 / (mat.density * 60 * (1793 - 293));  // chi / (rho c_p (T_m - T_r))
}

Real flow(const Material& /*mat*/, Real alpha) { return k_a + k_b * std::pow(alpha, k_n); }

Real softening(const Material& mat, Real w) {
    return 1.0 - std::pow(std::min(heating(mat) * w, 1.0), exponent(mat));
}

/// W(alpha) of dW/d alpha = sigma_f(alpha) Theta(W), W(0) = 0, by RK4 in steps of 1e-5.
Real work_by_runge_kutta(const Material& mat, Real alpha_end) {
    auto rate = [&](Real alpha, Real w) { return flow(mat, alpha) * softening(mat, w); };
    const int n = static_cast<int>(std::ceil(alpha_end / 1e-5));
    const Real h = alpha_end / n;
    Real w = 0;
    for (int i = 0; i < n; ++i) {
        const Real a = i * h;
        const Real k1 = rate(a, w), k2 = rate(a + h / 2, w + h / 2 * k1),
                   k3 = rate(a + h / 2, w + h / 2 * k2), k4 = rate(a + h, w + h * k3);
        w += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return w;
}

/// W(alpha) in closed form for m = 1.
Real work_closed_form(const Material& mat, Real alpha) {
    const Real f = k_a * alpha + k_b * std::pow(alpha, k_n + 1) / (k_n + 1);
    return (1.0 - std::exp(-heating(mat) * f)) / heating(mat);
}

TEST(ThermalSoftening, TheRungeKuttaReferenceEqualsTheClosedForm) {
    // to 1e-8: RK4 loses its order near alpha = 0, where alpha^n has an unbounded slope
    const Material mat = hot_steel(1.0);
    EXPECT_NEAR(work_by_runge_kutta(mat, 0.8), work_closed_form(mat, 0.8),
                1e-8 * work_closed_form(mat, 0.8));
}

/// The scalar update driven by equal strain increments in x and y to eps = 0.4.
MaterialPoint stretched_point(const Material& mat) {
    const J2Plastic j2 = make_j2_plastic(mat);
    MaterialPoint mp;
    for (int i = 0; i < 4000; ++i) j2.update(mp, Voigt3(1e-4, 1e-4, 0), 1e-6, mp);
    return mp;
}

TEST(ThermalSoftening, AnEquibiaxialStretchFollowsTheAdiabaticCurve) {
    for (const Real m_exponent : {1.0, 0.5}) {
        SCOPED_TRACE(m_exponent);
        const Material mat = hot_steel(m_exponent);
        const MaterialPoint mp = stretched_point(mat);
        const Real alpha = mp.plastic_strain;
        ASSERT_GT(alpha, 0.7);  // eps = 0.4 each way: alpha = 2 eps_p11 ~ 0.8
        const Real w_ref = work_by_runge_kutta(mat, alpha);
        const Real sigma_ref = flow(mat, alpha) * softening(mat, w_ref);
        // the temperature of each increment is that of its start: a lag of one increment
        // (d alpha = 2e-4) in W, ~1e-4 of it; the return itself is exact on this path
        EXPECT_NEAR(mp.plastic_work, w_ref, 1e-3 * w_ref);
        EXPECT_NEAR(mp.stress(0), sigma_ref, 1e-3 * sigma_ref);
        EXPECT_NEAR(mp.stress(1), sigma_ref, 1e-3 * sigma_ref);
        // the softening is large: T* ~ 0.5, the stress well below the isothermal one
        EXPECT_LT(mp.stress(0), 0.8 * flow(mat, alpha));
    }
}

TEST(ThermalSoftening, WithoutHeatTheMaterialIsTheIsothermalOneBitForBit) {
    Material hot = hot_steel(1.0), cold = hot;
    std::any_cast<J2Parameters&>(cold.parameters).thermal = ThermalSoftening{};
    std::any_cast<J2Parameters&>(hot.parameters).thermal =
        adiabatic_softening(1.0, 1793, 293, 1e300, 0.9, hot.density);  // no temperature rise
    MaterialPoint a = stretched_point(hot), b = stretched_point(cold);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a.stress(k), b.stress(k));
    EXPECT_EQ(a.plastic_strain, b.plastic_strain);
}

TEST(ThermalSoftening, TheFactorStopsAtItsFloorAtTheMeltingPoint) {
    ThermalSoftening t;
    t.active = true;
    t.m = 1;
    t.heating = 1.0;
    EXPECT_EQ(t.factor(0.0), 1.0);
    EXPECT_NEAR(t.factor(0.25), 0.75, 1e-15);
    EXPECT_EQ(t.factor(2.0), ThermalSoftening::k_min_factor);
    const RealPack w([](auto l) { return 0.1 * static_cast<Real>(l); });
    const RealPack f = t.factor(w);
    for (int l = 0; l < k_lanes; ++l) EXPECT_EQ(lane(f, l), t.factor(0.1 * l));
}

/// A 1 m square of 4 x 4 squares stretched equibiaxially, every particle at its own constant
/// velocity (x0, y0, 0): lambda = 1 + t, to 1.4. Its elements (in SIMD blocks) take the path of
/// the test above, in the solver's incremental strains (eps = ln 1.4 = 0.336 each way).
TEST(ThermalSoftening, APlateStretchedInTheSolverFollowsTheAdiabaticCurve) {
    PlateParams pp;
    pp.nx = pp.ny = 4;
    Model m = test::one_section_model(generate_plate(pp), 0.01);
    m.materials[0] = hot_steel(1.0);
    m.sections[0].thickness_points = 5;
    m.control.end_time = 0.4;
    test::prescribe_velocity_field(m, [](const Vec3& x0) { return Vec3(x0.x(), x0.y(), 0); },
                                   {false, false, false, true, true, true});
    ExplicitSolver s(m);
    while (s.time() < m.control.end_time) s.step(m.control.end_time - s.time());
    for (const Index e : {Index{0}, Index{17}, Index{31}}) {
        const MaterialPoint mp = s.elements().point_state(e, 0);
        const Real alpha = mp.plastic_strain;
        ASSERT_GT(alpha, 0.6);
        const Real w_ref = work_by_runge_kutta(m.materials[0], alpha);
        const Real sigma_ref = flow(m.materials[0], alpha) * softening(m.materials[0], w_ref);
        // the lag of one step in the temperature, as above, over steps of d alpha ~ 1e-4
        EXPECT_NEAR(mp.plastic_work, w_ref, 1e-3 * w_ref);
        EXPECT_NEAR(mp.stress(0), sigma_ref, 1e-3 * sigma_ref);
    }
}

}  // namespace
}  // namespace fpmshell

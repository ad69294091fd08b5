// GISSMO's fading (failure/tabulated/, theory.md eq. 7.6-6): once the material is unstable the
// damage fades the stress a point carries, sigma_nominal = (1 - w) sigma,
// w = ((D - D_c) / (1 - D_c))^m. On the homogeneous uniaxial path every element's membrane
// force is (1 - w) h sigma of its points, w of the damage at the last step, from the
// instability on (at a critical strain or at a critical damage); the element carries nothing
// when it erodes, and the energy balance (the fading's work in the strain work) closes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fpmshell/failure/tabulated/tabulated_failure.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "homogeneous_paths.hpp"

namespace fpmshell {
namespace {

constexpr Real k_failure_strain = 0.2;  // flat: the path's triaxiality moves at the yield
constexpr Real k_thickness = 0.01;      // damaging_path's

TabulatedFailureParameters gissmo(TabulatedFailureParameters::Fading fading) {
    TabulatedFailureParameters p;
    p.failure_strain = {{0.0, k_failure_strain}};
    p.exponent = 2;
    p.fading = std::move(fading);
    return p;
}

TEST(GissmoFading, TheFadingOfTheDamageAfterTheInstability) {
    TabulatedFailureParameters::Fading f;
    f.exponent = {{0.1, 2.0}, {0.3, 4.0}};  // against the element size
    const TabulatedFailure t(gissmo(f));
    EXPECT_EQ(t.fading(0.1, 0.2, 0.1), 0.0);                     // below D_c
    EXPECT_DOUBLE_EQ(t.fading(0.6, 0.2, 0.1), 0.25);             // (0.4 / 0.8)^2
    EXPECT_DOUBLE_EQ(t.fading(0.6, 0.2, 0.2), 0.125);            // m = 3
    EXPECT_DOUBLE_EQ(t.fading(0.6, 0.2, 9.0), 0.0625);           // m = 4, held past the end
    EXPECT_EQ(t.fading(1.0, 0.2, 0.1), 1.0);                     // nothing carried at D = 1
    EXPECT_EQ(TabulatedFailure(gissmo({})).state_fields(), 6u);  // F, alpha, I, D_c, w, w
    EXPECT_EQ(TabulatedFailure(gissmo({})).fading_field(), 4u);
    TabulatedFailureParameters plain = gissmo({});
    plain.fading.reset();
    EXPECT_EQ(TabulatedFailure(plain).state_fields(), 2u);
    EXPECT_EQ(TabulatedFailure(plain).fading_field(), PointFailure::k_no_field);
}

/// The uniaxial path to erosion: every step, the first element's membrane force N_xx against
/// (1 - w) h sigma_xx of its first point, w the fading expected from the plastic strain of the
/// step before (the criterion judges after the step, the element fades by it in the next);
/// the largest relative difference, the largest |energy error|, N_xx at the peak and at the
/// step before the erosion.
struct FadingRun {
    Real worst_difference = 0, worst_energy_error = 0, peak = 0, last = 0;
    bool eroded = false;
};

/// With `alone`, the element watched is computed alone (the general element), not in a SIMD
/// block: the first 4 elements are in a second section of their own, too few for a block.
FadingRun run_uniaxial(const TabulatedFailureParameters& p, Real critical_strain,
                       Real critical_damage, bool alone = false) {
    const test::HomogeneousPath uniaxial = test::homogeneous_paths()[2];
    Model m = test::damaging_path(uniaxial.velocity, true, {"tabulated", p});
    if (alone) {
        m.sections.push_back(m.sections[0]);
        for (std::size_t e = 0; e < 4; ++e) m.element_section[e] = 1;
    }
    ExplicitSolver s(m);
    const TabulatedFailure t(p);
    const Real m_fade = p.fading->exponent.front().second;
    // the damage of the instability: at the step the plastic strain reaches the critical
    // strain (D = F^n there), or the critical damage
    Real d_c = critical_damage;
    bool unstable = false;
    FadingRun r;
    Real alpha_before = 0;
    while (s.eroded_elements() == 0 && s.time() < 1) {
        s.step(1e30);
        if (s.eroded_elements() > 0) break;
        const MaterialPoint point = s.elements().point_state(0, 0);
        const Real d_before = t.damage(std::min(alpha_before / k_failure_strain, 1.0));
        if (!unstable && alpha_before > 0) {
            unstable = critical_strain > 0 ? alpha_before >= critical_strain : d_before >= d_c;
            if (unstable && critical_strain > 0) d_c = d_before;
        }
        const Real w =
            unstable && d_before > d_c ? std::pow((d_before - d_c) / (1 - d_c), m_fade) : 0.0;
        const Real n_xx = s.elements().membrane_force(0)(0);
        const Real expected = (1 - w) * k_thickness * point.stress(0);
        r.worst_difference =
            std::max(r.worst_difference, std::abs(n_xx - expected) / (k_thickness * 2.5e8));
        r.worst_energy_error = std::max(r.worst_energy_error, std::abs(s.energy().error()));
        r.peak = std::max(r.peak, n_xx);
        r.last = n_xx;
        alpha_before = point.plastic_strain;
    }
    r.eroded = s.eroded_elements() > 0;
    return r;
}

TEST(GissmoFading, FromACriticalStrainTheElementCarriesTheFadedStress) {
    TabulatedFailureParameters::Fading f;
    f.critical_strain = {{0.0, 0.1}};
    f.exponent = {{0.0, 2.0}};
    for (const bool alone : {false, true}) {
        SCOPED_TRACE(alone ? "an element computed alone" : "an element of a SIMD block");
        const FadingRun r = run_uniaxial(gissmo(f), 0.1, 0, alone);
        EXPECT_TRUE(r.eroded);
        // the same numbers up to the rounding of the element's sums (5 points through the
        // thickness, the resultant of a triangle in its own frame: 1e-12 of the yield force)
        EXPECT_LT(r.worst_difference, 1e-9);
        // at D -> 1 nothing is left to carry: the step before the erosion carries under 2 % of the
        // peak (the damage of that step is 1 less one step's increment)
        EXPECT_LT(r.last, 0.02 * r.peak);
        EXPECT_LT(r.worst_energy_error, 1e-3);
    }
}

TEST(GissmoFading, FromACriticalDamageOfZeroTheStressFadesFromTheFirstYield) {
    TabulatedFailureParameters::Fading f;  // LS-DYNA's blank ECRIT and DCRIT
    f.critical_damage = 0;
    const FadingRun r = run_uniaxial(gissmo(f), 0, 0);
    EXPECT_TRUE(r.eroded);
    EXPECT_LT(r.worst_difference, 1e-9);
    EXPECT_LT(r.last, 0.02 * r.peak);
    EXPECT_LT(r.worst_energy_error, 1e-3);
}

TEST(GissmoFading, WithoutFadingThePointCarriesItsStressUntilTheElementErodes) {
    TabulatedFailureParameters p = gissmo({});
    p.fading.reset();
    const test::HomogeneousPath uniaxial = test::homogeneous_paths()[2];
    const Model m = test::damaging_path(uniaxial.velocity, true, {"tabulated", p});
    ExplicitSolver s(m);
    Real last = 0;
    while (s.eroded_elements() == 0 && s.time() < 1) {
        s.step(1e30);
        if (s.eroded_elements() == 0) {
            last = s.elements().membrane_force(0)(0);
            // (the rounding of the sum over the 5 points through the thickness)
            EXPECT_NEAR(last, k_thickness * s.elements().point_state(0, 0).stress(0),
                        1e-12 * k_thickness * 2.5e8);
        }
    }
    EXPECT_GT(last, k_thickness * 2.5e8);  // hardened past the yield, whole
}

}  // namespace
}  // namespace fpmshell

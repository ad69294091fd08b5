// A tabulated flow curve (theory.md §7.2, eq. 7.2-4) through the whole solver: the element
// blocks' trial check and SIMD return mapping, the stored flow radius and slope, the energy.
// - a tabulated straight line runs a plastic plate as the bilinear material does;
// - a curve of several points, crossed during the run, keeps the energy balance;
// - a table of identical curves at several rates runs as its one curve; a table whose curves
//   rise with the rate resists more (the plate's rates, ~10-100 /s, select the higher curves).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/materials/tabulated/tabulated_law.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "one_section_model.hpp"
#include "plate_runs.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_yield = 2.5e8;

/// A simply supported 1 m plate, 10 mm thick, every free particle thrown at 20 m/s against the
/// normal: it bends far past yield within a few hundred steps.
Model impulsed_plate(const Material& material) {
    Model m = test::alternate_plate(12, 0.01);
    test::simply_support(m);
    m.materials[0] = material;
    m.sections[0].thickness_points = 5;
    m.control.end_time = 1;
    InitialVelocity iv;
    for (Index p = 0; p < m.n_particles(); ++p) iv.nodes.push_back(p);
    iv.velocity = Vec3(0, 0, -20.0);
    m.initial_conditions.push_back(iv);
    return m;
}

Material steel() { return {"steel", "elastic", 7800, 2.1e11, 0.3}; }

/// A tabulated steel of those curves and that hardening mix.
Material tabulated(const std::vector<FlowCurvePoints>& curves, Real mix = 0.5) {
    Material s = steel();
    make_tabulated(s, curves).hardening_mix = mix;
    return s;
}

}  // namespace

TEST(TabulatedPlate, AStraightLineRunsAsTheBilinearMaterial) {
    Material bilinear = steel();
    const Real tangent = 2.1e9;
    make_bilinear(bilinear, k_yield, tangent).hardening_mix = 0.5;  // the slope enters b too
    const Real h = bilinear.youngs_modulus * tangent / (bilinear.youngs_modulus - tangent);
    const Material line = tabulated({{0.0, {0.0, 1.0}, {k_yield, k_yield + h}}});
    const Model model_a = impulsed_plate(bilinear), model_b = impulsed_plate(line);
    ExplicitSolver a(model_a), b(model_b);  // a solver refers to its model
    for (int i = 0; i < 300; ++i) {
        a.step(1e30);
        b.step(1e30);
    }
    // the variable step follows the deformed elements: the same to the states' agreement
    ASSERT_NEAR(a.time(), b.time(), 1e-9 * a.time());
    Real largest = 0, difference = 0;
    for (std::size_t p = 0; p < a.state().x.size(); ++p) {
        largest = std::max(largest, (a.state().x[p] - a.state().x_prev[p]).norm());
        difference = std::max(difference, (a.state().x[p] - b.state().x[p]).norm());
    }
    // the two curves differ in the last bits of the slope h (stored as a segment's slope): the
    // returns agree to their Newton tolerance (1e-10 relative), and 300 steps keep that far
    // below a millionth of the plate's deflection (about 0.1 m)
    EXPECT_LT(difference, 1e-7) << "largest step " << largest;
    EXPECT_GT(a.energy().plastic, 0.2 * a.energy().external_work)
        << "the plate must be well into the plastic range";
    EXPECT_NEAR(a.energy().plastic, b.energy().plastic, 1e-8 * a.energy().plastic);
}

TEST(TabulatedPlate, ACurveOfSeveralPointsKeepsTheEnergyBalance) {
    const Material curve = tabulated(
        {{0.0,
          {0.0, 0.002, 0.006, 0.012, 0.018, 0.1},
          {k_yield, 1.2 * k_yield, 1.3 * k_yield, 1.3 * k_yield, 1.35 * k_yield, 1.6 * k_yield}}});
    const Model m = impulsed_plate(curve);
    // the bound of benchmarks.md §1 (1e-3 of the largest energy) over the run
    EXPECT_LT(test::max_energy_error(m, 400), 1e-3);
    ExplicitSolver s(m);
    for (int i = 0; i < 400; ++i) s.step(1e30);
    EXPECT_GT(s.energy().plastic, 0.2 * s.energy().external_work);
    Real most = 0;  // the curve's points are crossed, up to its last segment
    for (Index e = 0; e < m.n_elements(); ++e)
        for (int k = 0; k < s.elements().thickness_points(e); ++k)
            most = std::max(most, s.elements().plastic_strain(e, k));
    EXPECT_GT(most, 0.018);
}

namespace {

/// The deflection of the plate's middle after 400 steps, and the plastic dissipation.
std::pair<Real, Real> deflection_and_dissipation(const Material& material) {
    const Model m = impulsed_plate(material);
    ExplicitSolver s(m);
    for (int i = 0; i < 400; ++i) s.step(1e30);
    Real deepest = 0;
    for (std::size_t p = 0; p < m.nodes.size(); ++p)
        deepest = std::max(deepest, m.nodes[p].z() - s.state().x[p].z());
    return {deepest, s.energy().plastic};
}

}  // namespace

TEST(TabulatedPlate, ATableOfOneCurveRunsAsThatCurveAndRisingCurvesResistMore) {
    const FlowCurvePoints curve{0.0, {0.0, 0.005, 0.1}, {k_yield, 1.2 * k_yield, 1.5 * k_yield}};
    // a table of several rates is isotropic (LS-DYNA *MAT_024)
    const Material one = tabulated({curve}, 1.0);
    std::vector<FlowCurvePoints> same_curves = {curve, curve, curve};
    same_curves[1].strain_rate = 1.0;
    same_curves[2].strain_rate = 100.0;
    std::vector<FlowCurvePoints> rising_curves = same_curves;
    for (Real& stress : rising_curves[1].stress) stress *= 1.5;
    for (Real& stress : rising_curves[2].stress) stress *= 2.0;
    const Material same = tabulated(same_curves, 1.0), rising = tabulated(rising_curves, 1.0);
    const auto [w_one, d_one] = deflection_and_dissipation(one);
    const auto [w_same, d_same] = deflection_and_dissipation(same);
    const auto [w_rising, d_rising] = deflection_and_dissipation(rising);
    // the same curve wherever the rate puts a point: the returns agree to their Newton
    // tolerance (1e-10 relative), far below 1e-7 of the ~0.1 m deflection after 400 steps
    EXPECT_NEAR(w_same, w_one, 1e-7 * w_one);
    EXPECT_NEAR(d_same, d_one, 1e-7 * d_one);
    EXPECT_GT(w_one, 0.02);  // it did bend well past yield
    // curves 1.5 to 2 times higher at the plate's rates: clearly less deflection
    EXPECT_LT(w_rising, 0.9 * w_one);
}

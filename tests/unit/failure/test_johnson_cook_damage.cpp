// Johnson-Cook damage (failure/johnson_cook/, theory.md eq. 7.6-2): the failure strain against
// triaxiality, rate and temperature; homogeneous paths in the solver that erode where
// D = alpha / eps_f(eta) reaches 1; a two-stage path whose damage adds up as the formula says;
// the criterion from a model file.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "fpmshell/failure/element_erosion.hpp"
#include "fpmshell/failure/johnson_cook/johnson_cook_damage.hpp"
#include "fpmshell/failure/stress_triaxiality.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "homogeneous_paths.hpp"

namespace fpmshell {
namespace {

// D1 + D2 exp(D3 eta): 0.35 in shear, 0.232 in uniaxial tension, 0.176 in plane strain,
// 0.160 equibiaxially
const JohnsonCookDamageParameters k_damage{0.05, 0.3, -1.5, 0.0, 0.0, 1.0, 1e-6};

Real eps_f(Real eta) { return 0.05 + 0.3 * std::exp(-1.5 * eta); }

Real triaxiality(Real sxx, Real syy, Real sxy) { return stress_triaxiality(sxx, syy, sxy); }

TEST(JohnsonCookDamage, TriaxialityOfThePlaneStressStates) {
    const Real s = 3e8;
    EXPECT_DOUBLE_EQ(triaxiality(s, 0, 0), 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(triaxiality(s, s, 0), 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(triaxiality(s, s / 2, 0), 1.0 / std::sqrt(3.0));
    EXPECT_EQ(triaxiality(s, -s, 0), 0.0);
    EXPECT_EQ(triaxiality(0, 0, s), 0.0);
    EXPECT_DOUBLE_EQ(triaxiality(-s, 0, 0), -1.0 / 3.0);
    EXPECT_EQ(triaxiality(0, 0, 0), 0.0);
}

TEST(JohnsonCookDamage, TheFailureStrainHasItsThreeFactorsAndItsFloor) {
    JohnsonCookDamageParameters p = k_damage;
    p.d4 = 0.02;
    p.d5 = 0.6;
    p.reference_strain_rate = 2.0;
    const JohnsonCookDamage d(p, 0.0);
    // core/simd_math.hpp's exp and log: within 4 ulps of the library's
    EXPECT_DOUBLE_EQ(d.failure_strain(1.0 / 3.0, 0.0, 0.0), eps_f(1.0 / 3.0));
    EXPECT_DOUBLE_EQ(d.failure_strain(0.0, 1.0, 0.0), 0.35);  // below the reference rate: 1
    EXPECT_DOUBLE_EQ(d.failure_strain(0.0, 200.0, 0.5), 0.35 * (1 + 0.02 * std::log(100.0)) * 1.3);
    p.d1 = -0.6;  // a fit that goes negative at high triaxiality stops at the floor
    EXPECT_EQ(JohnsonCookDamage(p, 0.0).failure_strain(2.0, 0.0, 0.0), p.minimum_strain);
    // every lane of a pack as the point alone
    const RealPack eta([](auto l) { return -0.5 + 0.2 * static_cast<Real>(l); });
    const RealPack rate([](auto l) { return 10.0 * static_cast<Real>(l); });
    const RealPack lanes = d.failure_strain(eta, rate, RealPack(0.5));
    for (int l = 0; l < k_lanes; ++l)
        EXPECT_EQ(lane(lanes, l), d.failure_strain(lane(eta, l), lane(rate, l), 0.5));
}

TEST(JohnsonCookDamage, ItAccumulatesThePlasticStrainOverTheFailureStrain) {
    JohnsonCookDamageParameters p = k_damage;
    p.d4 = 0.1;
    p.d5 = 1.0;
    const Real heating = 1e-9;  // T* per unit plastic work
    const JohnsonCookDamage d(p, heating);
    RealPack state[2] = {RealPack(0.0), RealPack(0.0)};  // D, then alpha at the last step
    RealPack alpha(0.0), sxx(0.0), syy(0.0), sxy(0.0), work(0.0);
    set_lane(alpha, 0, 0.1);
    set_lane(sxx, 0, 3e8);
    set_lane(work, 0, 2e8);  // T* = 0.2
    FailurePacks in;
    in.m = 1;
    in.plastic_strain = &alpha;
    in.stress[0] = &sxx;
    in.stress[1] = &syy;
    in.stress[2] = &sxy;
    in.plastic_work = &work;
    MaskOf<RealPack> failed(false);
    EXPECT_FALSE(d.judge(in, 1e-3, state, &failed));  // d alpha / dt = 100
    const Real eps = eps_f(1.0 / 3.0) * (1 + 0.1 * std::log(100.0)) * 1.2;
    EXPECT_DOUBLE_EQ(lane(state[0], 0), 0.1 / eps);
    EXPECT_EQ(lane(state[1], 0), 0.1);
    for (int l = 1; l < k_lanes; ++l) EXPECT_EQ(lane(state[0], l), 0.0);  // no point there
    EXPECT_FALSE(d.judge(in, 1e-3, state, &failed));  // no plastic strain this step: no damage
    EXPECT_DOUBLE_EQ(lane(state[0], 0), 0.1 / eps);
    set_lane(alpha, 0, 0.1 + eps);  // past D = 1
    EXPECT_TRUE(d.judge(in, 1e-3, state, &failed));
    EXPECT_TRUE(lane(failed, 0));
    EXPECT_FALSE(lane(failed, 1));
}

TEST(JohnsonCookDamage, HomogeneousPathsErodeAtTheFailureStrainOfTheirTriaxiality) {
    for (const test::HomogeneousPath& path : test::homogeneous_paths()) {
        SCOPED_TRACE(path.name);
        const Model m =
            test::damaging_path(path.velocity, path.lateral_free, {"johnson_cook", k_damage});
        ExplicitSolver s(m);
        Real alpha_first = 0, worst_error = 0;
        while (s.eroded_elements() < m.n_elements() && s.time() < 1) {
            s.step(1e30);
            if (s.eroded_elements() > 0 && alpha_first == 0)
                alpha_first = s.elements().point_state(0, 0).plastic_strain;
            worst_error = std::max(worst_error, std::abs(s.energy().error()));
        }
        ASSERT_EQ(s.eroded_elements(), m.n_elements());
        const Real alpha_last = s.elements().point_state(0, 0).plastic_strain;
        const Real expected = eps_f(path.eta);
        // within 1 %: a step's increment (1e-4 of alpha here), the elements' damage apart by
        // their rounding (the path is homogeneous: they erode within a few steps) and, in plane
        // strain, the elastic stretch of the start where eta climbs from
        // (1 + nu) / 3 / sqrt(1 - nu + nu^2)
        EXPECT_GT(alpha_first, expected * 0.99);
        EXPECT_LT(alpha_last, expected * 1.01);
        EXPECT_LT(worst_error, 1e-3);
    }
}

TEST(JohnsonCookDamage, TwoStagesAddTheirDamageAsTheFormulaSays) {
    // a point strained in pure shear to alpha_1, then equibiaxially until it fails:
    // D = alpha_1 / eps_f(0) + (alpha - alpha_1) / eps_f(2/3) = 1 at failure
    Material steel{"steel", "elastic", 7800, 2.0e11, 0.3};
    make_bilinear(steel, 2.5e8, 1.0e9);
    steel.failure.criteria.push_back({"johnson_cook", k_damage});
    const J2Plastic j2 = make_j2_plastic(steel);
    const ElementErosion rule(steel, 1, 1);
    std::vector<RealPack> state(rule.alone_state_packs(), RealPack(0.0));
    MaterialPoint mp;
    const Real de = 1e-5, alpha_1 = 0.15;
    auto step = [&](const Voigt3& d_eps) {
        j2.update(mp, d_eps, 1e-5, mp);
        const auto fill = [&](ElementFailurePoints& points) {
            set_lane(points.plastic_strain[0], 0, mp.plastic_strain);
            for (int r = 0; r < 3; ++r)
                set_lane(points.stress[static_cast<std::size_t>(r)][0], 0, mp.stress(r));
            set_lane(points.plastic_work[0], 0, mp.plastic_work);
        };
        return rule.erodes(fill, 1e-5, state.data());
    };
    while (mp.plastic_strain < alpha_1) ASSERT_FALSE(step(Voigt3(de, -de, 0)));
    const Real stage_1 = mp.plastic_strain;
    bool failed = false;
    while (!failed && mp.plastic_strain < 1) failed = step(Voigt3(de, de, 0));
    ASSERT_TRUE(failed);
    const Real expected = stage_1 + (1.0 - stage_1 / eps_f(0.0)) * eps_f(2.0 / 3.0);
    // within 1 %: the turn of the stress from one state to the other takes a plastic strain of
    // the order of the elastic strain at yield (1e-3), a fraction of a per cent of alpha here
    EXPECT_NEAR(mp.plastic_strain, expected, 0.01 * expected);
    // and it is not the proportional answer of either stage (0.35 and 0.160)
    EXPECT_GT(std::abs(mp.plastic_strain - eps_f(2.0 / 3.0)), 0.1 * expected);
    EXPECT_GT(std::abs(mp.plastic_strain - eps_f(0.0)), 0.1 * expected);
}

}  // namespace
}  // namespace fpmshell

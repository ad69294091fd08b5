// Hill's normal anisotropy in the plane-stress return (theory.md eq. 7.1-3; LS-DYNA's *MAT_037):
// a perfectly plastic sheet of Lankford ratio R strained along a ray until its stress no longer
// changes reaches the closed-form points of Hill's 1948 yield surface
//   sigma11^2 + sigma22^2 - 2R/(1+R) sigma11 sigma22 + 2(1+2R)/(1+R) sigma12^2 = sigma_y^2:
// equibiaxial sigma_y sqrt((1+R)/2); plane strain (eps22 = 0) sigma11 = sigma_y (1+R)/sqrt(1+2R)
// with sigma22 = R/(1+R) sigma11; pure shear sigma_y sqrt((1+R)/(2(1+2R))). The plastic strain
// of a uniaxial stress state flows with width / thickness = R. R = 1 is von Mises bit for bit,
// and the SIMD lanes return what the scalar return does.
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/materials/j2/j2_plastic.hpp"
#include "fpmshell/materials/j2/j2_return_mapping.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_e = 200e9, k_nu = 0.3, k_sy = 250e6;

J2Plastic sheet(Real r, Real hardening = 0) {
    FlowStress f;
    f.yield_stress = k_sy;
    f.hardening = hardening;
    return J2Plastic(k_e, k_nu, f, RateFactor{}, 1.0, r);
}

/// The stress after n equal strain increments d_eps from rest (the state carried along).
MaterialPoint strained(const J2Plastic& m, const Voigt3& d_eps, int n) {
    MaterialPoint p;
    for (int k = 0; k < n; ++k) m.update(p, d_eps, 1e-6, p);
    return p;
}

/// Hill's equivalent stress of (s11, s22, s12) for Lankford ratio r.
Real hill(const Voigt3& s, Real r) {
    return std::sqrt(s(0) * s(0) + s(1) * s(1) - 2 * r / (1 + r) * s(0) * s(1) +
                     2 * (1 + 2 * r) / (1 + r) * s(2) * s(2));
}

}  // namespace

TEST(HillAnisotropy, StrainRaysReachTheClosedFormPointsOfTheSurface) {
    for (const Real r : {0.5, 1.0, 1.6, 2.5}) {
        SCOPED_TRACE(::testing::Message() << "R = " << r);
        const J2Plastic m = sheet(r);
        // 400 increments of 1e-4: 40 times the yield strain, the elastic part long settled. The
        // return lands on the surface to its tolerance (1e-10 of sigma_y^2 / 3); the rays' limits
        // are reached to the ratio of the elastic to the total increment's drift, 1e-12 here
        const Real tol = 1e-6 * k_sy;
        const MaterialPoint bi = strained(m, Voigt3(1e-4, 1e-4, 0), 400);
        EXPECT_NEAR(bi.stress(0), k_sy * std::sqrt((1 + r) / 2), tol);
        EXPECT_NEAR(bi.stress(1), bi.stress(0), tol);
        const MaterialPoint plane = strained(m, Voigt3(1e-4, 0, 0), 400);
        EXPECT_NEAR(plane.stress(0), k_sy * (1 + r) / std::sqrt(1 + 2 * r), tol);
        EXPECT_NEAR(plane.stress(1), r / (1 + r) * plane.stress(0), tol);
        const MaterialPoint shear = strained(m, Voigt3(0, 0, 1e-4), 400);
        EXPECT_NEAR(shear.stress(2), k_sy * std::sqrt((1 + r) / (2 * (1 + 2 * r))), tol);
        for (const MaterialPoint* p : {&bi, &plane, &shear})
            EXPECT_NEAR(hill(p->stress, r), k_sy, 1e-9 * k_sy);
    }
}

TEST(HillAnisotropy, UniaxialPlasticFlowHasTheLankfordRatio) {
    // a perfectly plastic point at the uniaxial yield stress strained along Hill's flow direction
    // dgamma (s11 - R/(1+R) s22, s22 - R/(1+R) s11, ...) of the test's own surface: the return
    // keeps it where it is (its elastic part 1e-9 of the step) exactly when the code's surface
    // is Hill's, and the plastic increment then has width / thickness = R
    for (const Real r : {0.5, 1.6, 2.5}) {
        SCOPED_TRACE(::testing::Message() << "R = " << r);
        const J2Plastic m = sheet(r);
        MaterialPoint p;
        p.stress = Voigt3(k_sy, 0, 0);
        const Real dg = 1e-3 / k_sy;  // d(sigma_eq^2)/d(sigma) / 2 per unit: a 1e-3 strain step
        const Voigt3 d_eps(dg * k_sy, dg * (-r / (1 + r) * k_sy), 0);
        MaterialPoint q;
        m.update(p, d_eps, 1e-6, q);
        EXPECT_LT((q.stress - p.stress).norm(), 1e-6 * k_sy);
        const Voigt3 d_plastic = d_eps - m.stiffness().inverse() * (q.stress - p.stress);
        const Real thickness = -(d_plastic(0) + d_plastic(1));
        EXPECT_NEAR(d_plastic(1) / thickness, r, 1e-6 * r);
    }
}

TEST(HillAnisotropy, ROneIsVonMisesBitForBit) {
    FlowStress f;
    f.yield_stress = k_sy;
    f.hardening = 2e9;
    const J2Plastic von_mises(k_e, k_nu, f, RateFactor{}, 0.5);
    const J2Plastic r_one(k_e, k_nu, f, RateFactor{}, 0.5, 1.0);
    for (const Voigt3& d : {Voigt3(2e-3, -1e-3, 5e-4), Voigt3(1e-3, 1e-3, 0), Voigt3(0, 0, 3e-3)}) {
        const MaterialPoint a = strained(von_mises, d, 7), b = strained(r_one, d, 7);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(a.stress(k), b.stress(k));
        EXPECT_EQ(a.plastic_strain, b.plastic_strain);
        EXPECT_EQ(a.plastic_work, b.plastic_work);
    }
}

TEST(HillAnisotropy, EveryLaneEqualsItsScalarReturn) {
    const J2ReturnConstants c = sheet(1.8, 3e9).return_constants();
    ASSERT_TRUE(c.anisotropic);
    J2PointState<RealPack> old{};
    std::array<RealPack, 3> d_eps{};
    std::array<J2PointState<Real>, k_lanes> old_l{};
    std::array<std::array<Real, 3>, k_lanes> d_l{};
    for (int l = 0; l < k_lanes; ++l) {  // rays of every direction, each past yield
        const Real angle = 0.7 * l + 0.3;
        d_l[static_cast<std::size_t>(l)] = {4e-3 * std::cos(angle), 4e-3 * std::sin(angle),
                                            1e-3 * std::sin(3 * angle)};
    }
    for (std::size_t k = 0; k < 3; ++k) {
        old.stress[k] = old.back_stress[k] = RealPack(0.0);
        d_eps[k] = RealPack([&](auto l) { return d_l[static_cast<std::size_t>(l)][k]; });
    }
    old.plastic_strain = old.flow_radius = old.flow_slope = RealPack(0.0);
    const RealPack one(1.0);
    const J2Return<RealPack> out = j2_return_mapping(c, old, d_eps, one, one > 0.0);
    for (int l = 0; l < k_lanes; ++l) {
        const auto ul = static_cast<std::size_t>(l);
        const J2Return<Real> ref = j2_return_mapping(c, old_l[ul], d_l[ul], 1.0, true);
        ASSERT_TRUE(ref.yielded);
        // as the von Mises lanes: FMA contraction may differ, within the Newton tolerance
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_NEAR(lane(out.state.stress[k], l), ref.state.stress[k], 1e-9 * k_sy);
        EXPECT_NEAR(lane(out.plastic_work, l), ref.plastic_work, 1e-9 * std::abs(ref.plastic_work));
    }
}

// Spot welds that tear out of the sheet (solver/weld_sheet_strain.hpp, theory.md eq. 6.11-15):
// the lap joint of test_spot_weld_failure.cpp in a plastic steel (yield 100 MPa, the pull's
// 150 MPa in the pulled sheet yields it), its welds failing by the sheets' plastic strain alone.
// - Each followed particle's value is the mean of its elements' plastic strains (each averaged
//   over its points) weighted by their initial areas, recomputed here from the elements.
// - Each weld holds while the value at every one of its particles is below its plastic strain
//   and lets go in the step the largest reaches it, for good; out of reach, none lets go.
#include <gtest/gtest.h>

#include <algorithm>

#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "lap_joint.hpp"

using namespace fpmshell;
using test::lap_joint;
using test::LapJoint;

namespace {

constexpr Real k_end_time = 3e-3;  // the pull is full from 2 ms on

LapJoint plastic_lap_joint(Real plastic_strain) {
    NodalRigidBody::Failure failure;
    failure.plastic_strain = plastic_strain;
    LapJoint j = lap_joint(2, 6e4, failure);
    make_bilinear(j.model.materials[0], 1e8, 1e9);
    return j;
}

/// Eq. 6.11-15 recomputed: the mean of p's elements' plastic strains by their initial areas.
Real sheet_strain_at(const ExplicitSolver& s, const Model& m, Index p) {
    Real weighted = 0, area = 0;
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        const auto& t = m.triangles[e];
        if (std::find(t.begin(), t.end(), p) == t.end()) continue;
        const Vec3& a = m.nodes[static_cast<std::size_t>(t[0])];
        const Real a_e = 0.5 * (m.nodes[static_cast<std::size_t>(t[1])] - a)
                                   .cross(m.nodes[static_cast<std::size_t>(t[2])] - a)
                                   .norm();
        weighted += a_e * s.elements().mean_plastic_strain(static_cast<Index>(e));
        area += a_e;
    }
    return weighted / area;
}

/// The largest value at the particles of weld w.
Real weld_strain(const ExplicitSolver& s, const LapJoint& j, std::size_t w) {
    Real largest = 0;
    for (const Index p : j.model.nodal_rigid_bodies[w].nodes)
        largest = std::max(largest, s.weld_sheet_strain().at(p));
    return largest;
}

}  // namespace

// The value at each weld particle is the area-weighted mean of its elements' (to rounding: the
// same sums in another order), in every step, and it grows once the sheets yield.
TEST(SpotWeldDuctileFailure, TheSheetsStrainIsTheAreaWeightedMeanOfTheElements) {
    const LapJoint j = plastic_lap_joint(1e9);
    ExplicitSolver s(j.model);
    ASSERT_EQ(s.weld_sheet_strain().particles().size(), 12u);  // 6 welds of 2 particles
    Real largest = 0;
    while (s.time() < k_end_time) {
        s.step(1e30);
        for (const Index p : s.weld_sheet_strain().particles()) {
            const Real expected = sheet_strain_at(s, j.model, p);
            EXPECT_NEAR(s.weld_sheet_strain().at(p), expected, 1e-14 * (1 + expected))
                << "particle " << p << ", t " << s.time();
            largest = std::max(largest, expected);
        }
    }
    EXPECT_GT(largest, 1e-3);                     // the sheets did yield at the welds
    EXPECT_EQ(s.weld_sheet_strain().at(0), 0.0);  // the clamped edge's particle is not followed
}

// Eq. 6.11-15: with the failure strain at half the largest value the welds reach when they
// cannot fail, every weld holds while its value is below it and lets go in the step it
// reaches it; the pulled sheet leaves once all have. Out of reach, none lets go.
TEST(SpotWeldDuctileFailure, AWeldTearsOutWhenTheSheetsStrainReachesItsOwn) {
    Real reached = 0;
    {
        const LapJoint j = plastic_lap_joint(1e9);
        ExplicitSolver s(j.model);
        while (s.time() < k_end_time) {
            s.step(1e30);
            for (const std::size_t w : j.welds[1])
                reached = std::max(reached, weld_strain(s, j, w));
        }
        EXPECT_EQ(s.nodal_rigid_bodies().failed_welds(), 0u);
    }
    ASSERT_GT(reached, 1e-3);
    const Real eps_f = 0.5 * reached;
    const LapJoint j = plastic_lap_joint(eps_f);
    ExplicitSolver s(j.model);
    const NodalRigidBodies& bodies = s.nodal_rigid_bodies();
    std::vector<std::uint8_t> failed(j.model.nodal_rigid_bodies.size(), 0);
    while (s.time() < k_end_time) {
        s.step(1e30);
        for (const std::size_t w : j.welds[1]) {
            const bool now = bodies.welds_failed()[w] != 0;
            if (failed[w]) {
                EXPECT_TRUE(now) << "weld " << w << " held again at t " << s.time();
                continue;
            }
            EXPECT_EQ(now, weld_strain(s, j, w) >= eps_f)
                << "weld " << w << ", t " << s.time() << ", value " << weld_strain(s, j, w);
            failed[w] = now ? 1 : 0;
        }
    }
    EXPECT_EQ(bodies.failed_welds(), j.welds[1].size());
    // the pulled sheet left: its far edge is well beyond where the welds held it
    Real far = 0;
    for (const Index p : j.sheet[1])
        far = std::max(far, s.state().x[static_cast<std::size_t>(p)].x());
    EXPECT_GT(far, 0.9 + 0.01);
}
